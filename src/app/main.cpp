// wavepath: command-line entry point; every failure ends as one "wavepath: error:" line.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"wavepath: a wavefront path tracer for glTF scenes on Vulkan or OpenCL"};
  app.require_subcommand(1);
  wp::RenderOptions renderOptions;
  CLI::App* render = wp::addRenderCommand(app, renderOptions);
  wp::ViewOptions viewOptions;
  CLI::App* view = wp::addViewCommand(app, viewOptions);
  wp::MergeOptions mergeOptions;
  CLI::App* merge = wp::addMergeCommand(app, mergeOptions);
  CLI::App* devices = wp::addDevicesCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "wavepath: error: %s; run 'wavepath --help' for usage\n", e.what());
    return 2;
  }
  try {
    if (render->parsed()) {
      return wp::runRender(renderOptions);
    }
    if (view->parsed()) {
      viewOptions.sampleLimit = view->count("--spp") > 0;
      return wp::runView(viewOptions);
    }
    if (merge->parsed()) {
      return wp::runMerge(mergeOptions);
    }
    if (devices->parsed()) {
      return wp::runDevices();
    }
  } catch (const wp::FlagError& e) {
    std::fprintf(stderr, "wavepath: error: %s; run 'wavepath --help' for usage\n", e.what());
    return 2;
  } catch (const wp::Error& e) {
    std::fprintf(stderr, "wavepath: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wavepath: internal error: %s; please report it with the command line used\n", e.what());
    return 3;
  }
  return 0;
}

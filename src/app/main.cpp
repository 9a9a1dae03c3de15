// wavepath: command-line entry point; every failure ends as one "wavepath: error:" line.
#include <cstdio>
#include <exception>
#include <new>

#include "app/command_line.h"
#include "core/error.h"
#include "core/log.h"

int main(int argc, char** argv) {
  wp::CommandLine line;
  if (std::optional<int> exitCode = wp::parseCommandLine(line, argc, argv)) {
    return *exitCode;
  }
  try {
    if (line.render->parsed()) {
      return wp::runRender(line.renderOptions);
    }
    if (line.view->parsed()) {
      return wp::runView(line.viewOptions);
    }
    if (line.merge->parsed()) {
      return wp::runMerge(line.mergeOptions);
    }
    if (line.devices->parsed()) {
      return wp::runDevices();
    }
  } catch (const wp::FlagError& e) {
    std::fprintf(stderr, "wavepath: error: %s; run 'wavepath --help' for usage\n", e.what());
    return 2;
  } catch (const wp::Error& e) {
    wp::flushWarnings();
    std::fprintf(stderr, "wavepath: error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "wavepath: error: out of host memory; render a smaller image or scene, or free memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wavepath: internal error: %s; please report it with the command line used\n", e.what());
    return 3;
  }
  return 0;
}

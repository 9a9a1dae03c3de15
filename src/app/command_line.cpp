// The wavepath command line: subcommands, flags, and the check every number flag gets.
#include "app/command_line.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

namespace wp {
namespace {

// CLI11's range checks compare with < and >, which NaN passes, and a float flag given 1e39
// becomes infinity: every floating-point flag, whatever else it checks, first refuses
// anything but a finite number a float can hold. Added here to every flag CLI11 types as
// FLOAT, so a new flag cannot forget it.
void requireFiniteNumbers(CLI::App& command) {
  const CLI::Validator finite(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || std::fabs(value) > FLT_MAX) {
          return "'" + text + "' is not a finite number";
        }
        return "";
      },
      "");
  for (CLI::Option* option : command.get_options()) {
    if (option->get_type_name().rfind("FLOAT", 0) == 0) option->transform(finite);
  }
  for (CLI::App* sub : command.get_subcommands({})) requireFiniteNumbers(*sub);
}

}  // namespace

CommandLine::CommandLine() {
  app.require_subcommand(1);
  render = addRenderCommand(app, renderOptions);
  view = addViewCommand(app, viewOptions);
  merge = addMergeCommand(app, mergeOptions);
  devices = addDevicesCommand(app);
  requireFiniteNumbers(app);
}

std::optional<int> parseCommandLine(CommandLine& line, int argc, const char* const* argv) {
  try {
    line.app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return line.app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return line.app.exit(e);
  } catch (const CLI::Success&) {
    return 0;  // a flag did all that was asked (--passes list)
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "wavepath: error: %s; run 'wavepath --help' for usage\n", e.what());
    return 2;
  }
  line.viewOptions.sampleLimit = line.view->count("--spp") > 0;
  return std::nullopt;
}

}  // namespace wp

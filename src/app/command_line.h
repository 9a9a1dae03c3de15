// The wavepath command line: its subcommands and flags, parsed into their options.
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

#include "app/commands.h"

namespace wp {

// Every subcommand with its flags, and the options they fill in when parsed. Holds pointers
// into itself, so it stays where it was made.
struct CommandLine {
  CLI::App app{"wavepath: a wavefront path tracer for glTF scenes on Vulkan or OpenCL"};
  RenderOptions renderOptions;
  ViewOptions viewOptions;
  MergeOptions mergeOptions;
  CLI::App* render = nullptr;
  CLI::App* view = nullptr;
  CLI::App* merge = nullptr;
  CLI::App* devices = nullptr;

  CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;
};

// Parses argv into `line`. Returns the exit code when the program ends here: 0 after
// printing --help, 2 after printing one "wavepath: error:" line for a bad flag. Returns
// nothing when the chosen subcommand should run.
std::optional<int> parseCommandLine(CommandLine& line, int argc, const char* const* argv);

}  // namespace wp

// Runs the built CLI in a shell and captures what it printed, for tests of the command line.
#pragma once

#include <string>

namespace obscura::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr, interleaved
};

// Runs `obscura <arguments>` (arguments are passed to the shell as written).
CommandResult run_cli(const std::string& arguments);

// A fresh, empty directory under the system temp directory, removed at process exit.
std::string make_temp_dir(const std::string& prefix);

}  // namespace obscura::test

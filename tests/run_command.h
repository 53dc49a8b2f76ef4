// Runs the built CLI in a shell and captures what it printed, for tests of the command line.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace obscura::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr, interleaved
};

// Runs `obscura <arguments>` (arguments are passed to the shell as written).
CommandResult run_cli(const std::string& arguments);
// The shell command line run_cli runs.
std::string cli_command_line(const std::string& arguments);
// Runs a shell command line (e.g. with `ulimit` before the CLI); stdout and stderr captured.
CommandResult run_shell(const std::string& command_line);
// Runs the shell command lines side by side and waits for them all; their results in the order
// given. For independent commands that spend much of their time starting processes (the CLI
// loading its libraries, mpirun starting ranks) rather than computing.
std::vector<CommandResult> run_shells_concurrently(const std::vector<std::string>& command_lines);

// A command line the CLI must refuse, and what its message must say.
struct Refusal {
  std::string arguments, expected;
};
// Runs `obscura <prefix><refusal.arguments>` for every refusal, side by side: each must exit
// non-zero with its expected text in the output (checked with EXPECT, naming the arguments).
void expect_refusals(const std::string& prefix, const std::vector<Refusal>& refusals);

// Whether this build runs under AddressSanitizer, whose shadow memory needs terabytes of address
// space: `ulimit -v` cannot be used there (the process could not start).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

// "ulimit -v KB; " to bound a shell command's address space, or nothing under AddressSanitizer
// (whose own allocator limits then bound memory instead).
inline std::string address_space_limit(long kilobytes) {
  return kAddressSanitizer ? std::string() : "ulimit -v " + std::to_string(kilobytes) + "; ";
}

// A fresh, empty directory under the system temp directory, removed at process exit.
std::string make_temp_dir(const std::string& prefix);

// A test with its own empty temp directory, removed after the test.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = make_temp_dir("obscura-test"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const {
    return (std::filesystem::path(dir_) / name).string();
  }
  std::string dir_;
};

}  // namespace obscura::test

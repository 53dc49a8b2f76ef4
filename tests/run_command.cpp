#include "run_command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "test_paths.h"

namespace obscura::test {

CommandResult run_cli(const std::string& arguments) {
  return run_shell(cli_command_line(arguments));
}

std::string cli_command_line(const std::string& arguments) {
  // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"'" + std::string`.)
  std::string command(1, '\'');
  command.append(cli_path()).append("' ").append(arguments);
  return command;
}

namespace {

FILE* start_shell(const std::string& command_line) {
  std::string command = "{ " + command_line + "; } 2>&1";
  return popen(command.c_str(), "r");
}

CommandResult finish_shell(FILE* pipe) {
  CommandResult result;
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace

CommandResult run_shell(const std::string& command_line) {
  return finish_shell(start_shell(command_line));
}

std::vector<CommandResult> run_shells_concurrently(const std::vector<std::string>& command_lines) {
  // All started before any is read: a command blocked on a full pipe waits only until its turn
  // (popen closes the other commands' pipes in each child, so every pipe ends with its command).
  std::vector<FILE*> pipes;
  for (const std::string& line : command_lines) pipes.push_back(start_shell(line));
  std::vector<CommandResult> results;
  for (FILE* pipe : pipes) results.push_back(finish_shell(pipe));
  return results;
}

void expect_refusals(const std::string& prefix, const std::vector<Refusal>& refusals) {
  std::vector<std::string> commands;
  for (const Refusal& refusal : refusals)
    commands.push_back(cli_command_line(prefix + refusal.arguments));
  const std::vector<CommandResult> results = run_shells_concurrently(commands);
  for (size_t i = 0; i < refusals.size(); ++i) {
    EXPECT_NE(results[i].exit_code, 0) << refusals[i].arguments << "\n" << results[i].output;
    EXPECT_NE(results[i].output.find(refusals[i].expected), std::string::npos)
        << refusals[i].arguments << "\n"
        << results[i].output;
  }
}

std::string make_temp_dir(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  char* made = mkdtemp(pattern.data());
  return made ? std::string(made) : std::string();
}

}  // namespace obscura::test

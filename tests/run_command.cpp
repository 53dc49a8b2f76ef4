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
  // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"'" + std::string`.)
  std::string command(1, '\'');
  command.append(cli_path()).append("' ").append(arguments);
  return run_shell(command);
}

CommandResult run_shell(const std::string& command_line) {
  CommandResult result;
  std::string command = "{ " + command_line + "; } 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string make_temp_dir(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  char* made = mkdtemp(pattern.data());
  return made ? std::string(made) : std::string();
}

}  // namespace obscura::test

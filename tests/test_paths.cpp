#include "test_paths.h"

#include <filesystem>
#include <stdexcept>

namespace obscura::test {

std::string source_path(const std::string& relative) {
  return std::string(OBSCURA_SOURCE_DIR) + "/" + relative;
}

std::string data_path(const std::string& relative) {
  std::string path = std::string(OBSCURA_SOURCE_DIR) + "/tests/data/" + relative;
  if (!std::filesystem::exists(path))
    throw std::runtime_error("test data missing: tests/data/" + relative);
  return path;
}

std::string cli_path() {
  return OBSCURA_CLI_PATH;
}

}  // namespace obscura::test

#include "test_paths.h"

namespace obscura::test {

std::string source_path(const std::string& relative) {
  return std::string(OBSCURA_SOURCE_DIR) + "/" + relative;
}

std::string shared_path(const std::string& relative) {
  return std::string(OBSCURA_SOURCE_DIR) + "/../shared/" + relative;
}

std::string cli_path() { return OBSCURA_CLI_PATH; }

}  // namespace obscura::test

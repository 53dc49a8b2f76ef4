// Where tests find the project's files, the shared material beside the checkout, and the CLI.
#pragma once

#include <string>

namespace obscura::test {

std::string source_path(const std::string& relative);  // inside the repository
std::string shared_path(const std::string& relative);  // inside ../shared
std::string cli_path();                                // the built `obscura` executable

}  // namespace obscura::test

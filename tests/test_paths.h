// Where tests find the project's files, the shared material beside the checkout, and the CLI.
#pragma once

#include <string>

namespace obscura::test {

std::string source_path(const std::string& relative);  // inside the repository
std::string shared_path(const std::string& relative);  // inside ../shared (not in a user's clone)
// A file of the suite's own test data (tests/data/, licences in its README.md). Throws
// std::runtime_error naming the file when it is missing, so a test fails cleanly instead of crashing.
std::string data_path(const std::string& relative);
std::string cli_path();                                // the built `obscura` executable

}  // namespace obscura::test

// Where tests find the project's files and the CLI. Tests do not need ../shared: a user's clone
// does not have it. The one reader, the file corpus (render/file_corpus_test.cpp), renders
// ../shared/assets/gltf's models when CI has it beside the clone and skips them, saying so,
// when not.
#pragma once

#include <string>

namespace obscura::test {

std::string source_path(const std::string& relative);  // inside the repository
// A file of the suite's own test data (tests/data/, licences in its README.md). Throws
// std::runtime_error naming the file when it is missing, so a test fails cleanly instead of
// crashing.
std::string data_path(const std::string& relative);
std::string cli_path();  // the built `obscura` executable

}  // namespace obscura::test

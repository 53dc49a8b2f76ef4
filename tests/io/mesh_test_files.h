// Helpers for the OBJ/PLY/STL loader tests: writing small files into a temp folder, expecting
// an obscura::Error with given fragments, and little-endian/big-endian byte writers for binary
// PLY and STL built in the test.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "obscura/math/error.h"
#include "run_command.h"

namespace obscura::test {

inline std::string write_file(const std::string& dir, const std::string& name,
                              const std::string& bytes) {
  std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs `load` and expects an obscura::Error whose message has every fragment.
inline void expect_load_error(const std::function<void()>& load,
                              const std::vector<std::string>& fragments) {
  try {
    load();
    ADD_FAILURE() << "no error; expected one mentioning " << fragments.front();
  } catch (const Error& e) {
    for (const std::string& f : fragments) EXPECT_THAT(e.what(), testing::HasSubstr(f));
  }
}

// Appends `value`'s bytes in little- or big-endian order.
template <typename T>
void put(std::string& out, T value, bool big_endian = false) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace obscura::test

// Comparing the image files the CLI writes, for the tests of distributed rendering: the pixels
// bit for bit (an EXR's header holds the time it was written, so its bytes differ), whole files
// byte for byte, and the attributes that mark a partial render.
#pragma once

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "obscura/io/image_io.h"

namespace obscura::test {

// Whether two files hold the same image: size, channels and every stored value, bit for bit
// (NaN and infinities too).
inline ::testing::AssertionResult same_pixels(const std::string& actual,
                                              const std::string& expected) {
  Image a, e;
  try {
    a = read_image(actual);
    e = read_image(expected);
  } catch (const std::exception& error) {
    return ::testing::AssertionFailure() << error.what();
  }
  if (a.width != e.width || a.height != e.height || a.channels != e.channels)
    return ::testing::AssertionFailure()
           << actual << " is " << a.width << "x" << a.height << "x" << a.channels << ", "
           << expected << " " << e.width << "x" << e.height << "x" << e.channels;
  for (size_t i = 0; i < e.data.size(); ++i)
    if (std::memcmp(&a.data[i], &e.data[i], sizeof(float)) != 0) {
      const size_t pixel = i / size_t(e.channels);
      return ::testing::AssertionFailure()
             << actual << " and " << expected << " first differ at pixel ("
             << pixel % size_t(e.width) << ", " << pixel / size_t(e.width) << ") channel "
             << i % size_t(e.channels) << ": " << a.data[i] << " vs " << e.data[i];
    }
  return ::testing::AssertionSuccess();
}

// The whole file as text (a different name from test_files.h's file_bytes, which returns bytes:
// two inline functions with one name and different return types would break the one-definition
// rule, and the linker keeps one body for both).
inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A string attribute of the image's header as OpenImageIO reads it ("" when absent).
inline std::string image_attribute(const std::string& path, const std::string& name) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    ADD_FAILURE() << path << ": " << OIIO::geterror();
    return "";
  }
  return in->spec().get_string_attribute(name);
}

// The regular files in `directory`, by name, sorted: what a failed command must not have left.
inline std::vector<std::string> files_in(const std::string& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace obscura::test

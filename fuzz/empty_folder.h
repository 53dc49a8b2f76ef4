// Where fuzz targets resolve relative paths (mtllib, glTF URIs, JSON model names): an empty
// folder of the system temp directory, made once per process, so that an input cannot read the
// files around the fuzzer.
#pragma once

#include <filesystem>
#include <string>

namespace obscura::fuzz {

inline std::string make_empty_folder(const std::string& name) {
  std::filesystem::path folder = std::filesystem::temp_directory_path() / name;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  return folder.string();
}

}  // namespace obscura::fuzz

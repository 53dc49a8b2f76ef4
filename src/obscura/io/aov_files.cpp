#include "obscura/io/aov_files.h"

namespace obscura {

namespace {

std::string aov_path(const std::string& output, const std::string& name) {
  return output.substr(0, output.find_last_of('.')) + "." + name + ".exr";
}

}  // namespace

std::vector<std::string> aov_paths(const std::string& output, bool albedo) {
  std::vector<std::string> paths;
  for (const char* name : {"albedo", "normal", "depth", "range", "id"})
    if (albedo || std::string(name) != "albedo") paths.push_back(aov_path(output, name));
  return paths;
}

std::vector<std::string> write_aovs(const std::string& output, const AovBuffers& aovs,
                                    const ImageMetadata& metadata) {
  std::vector<std::string> paths;
  ImageWriteOptions write_options;
  write_options.metadata = metadata;
  for (const AovImage& aov : aovs.images()) {
    paths.push_back(aov_path(output, aov.name));
    write_image(paths.back(), aov.image, write_options);
  }
  return paths;
}

}  // namespace obscura

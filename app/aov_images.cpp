#include "aov_images.h"

namespace obscura::app {

namespace {

std::string stem_of(const std::string& output) {
  return output.substr(0, output.find_last_of('.'));
}

}  // namespace

std::vector<NamedImage> tracer_aov_images(const AovBuffers& aovs) {
  return {{"albedo", aovs.albedo()},
          {"normal", aovs.normal()},
          {"depth", aovs.depth()},
          {"id", aovs.id()}};
}

std::vector<std::string> write_aov_images(const std::string& output,
                                          const std::vector<NamedImage>& images,
                                          const ImageMetadata& metadata) {
  std::vector<std::string> paths;
  ImageWriteOptions write_options;
  write_options.metadata = metadata;
  for (const NamedImage& aov : images) {
    paths.push_back(stem_of(output) + "." + aov.name + ".exr");
    write_image(paths.back(), aov.image, write_options);
  }
  return paths;
}

std::vector<std::string> aov_paths(const std::string& output, const std::string& renderer) {
  std::vector<std::string> paths;
  for (const char* name : {"albedo", "normal", "depth", "id"})
    if (renderer != "raster" || std::string(name) != "albedo")
      paths.push_back(stem_of(output) + "." + name + ".exr");
  return paths;
}

}  // namespace obscura::app

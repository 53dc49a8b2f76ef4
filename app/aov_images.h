// The auxiliary images `obscura render --aovs` writes beside the image, for either renderer:
// by name, in the order they are written (render.png → render.albedo.exr, render.normal.exr, …).
#pragma once

#include <string>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/film/image.h"
#include "obscura/io/image_io.h"

namespace obscura::app {

struct NamedImage {
  std::string name;  // "albedo", "normal", "depth", "id"
  Image image;
};

// The tracer's: albedo, normal, depth (distance along the ray), id.
std::vector<NamedImage> tracer_aov_images(const AovBuffers& aovs);
// Writes each image to <output stem>.<name>.exr; returns the paths.
std::vector<std::string> write_aov_images(const std::string& output,
                                          const std::vector<NamedImage>& images,
                                          const ImageMetadata& metadata = {});
// The files --aovs writes beside `output` for a renderer ("raster" writes no albedo).
std::vector<std::string> aov_paths(const std::string& output, const std::string& renderer);

}  // namespace obscura::app

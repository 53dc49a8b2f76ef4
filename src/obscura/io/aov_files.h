// The one writer of AOVs: each of a frame's auxiliary images to its own OpenEXR file beside the
// image (render.png → render.albedo.exr, render.normal.exr, render.depth.exr, render.range.exr,
// render.id.exr), for either renderer. depth is along the optical axis, range along the ray.
#pragma once

#include <string>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/io/image_io.h"

namespace obscura {

// The files write_aovs writes beside `output`, in order: with `albedo`, the albedo first.
std::vector<std::string> aov_paths(const std::string& output, bool albedo);

// Writes AovBuffers::images() to <output stem>.<name>.exr (with `metadata`, e.g. that the render
// is partial); returns the paths. Throws obscura::Error when a file cannot be written.
std::vector<std::string> write_aovs(const std::string& output, const AovBuffers& aovs,
                                    const ImageMetadata& metadata = {});

}  // namespace obscura

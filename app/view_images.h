// The live view's images as the page shows them: PNG files in memory, made by the same image
// codecs plugin that writes `obscura render`'s files (io/image_codecs.h).
#pragma once

#include <string>

#include "obscura/color/develop.h"
#include "obscura/film/image.h"

namespace obscura::app {

// The finished linear frame developed as `obscura render -o frame.png` develops it with the same
// display settings (8-bit: more bits are written as 8 here), so the page's pixels are the file's.
std::string beauty_png(const Image& linear, DisplaySettings display);

// Depth along the optical axis (one channel, +∞ where nothing was hit) on a colour scale from
// near (dark blue) to far (yellow) between the frame's nearest and farthest finite depths; misses
// black. `near_m` and `far_m` receive the scale's ends.
std::string depth_png(const Image& depth, double* near_m = nullptr, double* far_m = nullptr);

// World-space normals as colours, (n + 1) / 2; misses black.
std::string normal_png(const Image& normal);

// Mesh ids as colours, a fixed well-spread colour per id; misses (−1) black.
std::string id_png(const Image& id);

}  // namespace obscura::app

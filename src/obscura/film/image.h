// A plain image: width × height pixels of `channels` floats, row 0 at the top.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "obscura/color/rgb.h"

namespace obscura {

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> data;                 // row-major, interleaved channels
  std::vector<std::string> channel_names;  // e.g. {"R", "G", "B"}; empty means the defaults

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c), data(size_t(w) * h * c, 0.f) {}

  float& at(int x, int y, int c) { return data[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return data[(size_t(y) * width + x) * channels + c]; }
  Rgb rgb(int x, int y) const { return {at(x, y, 0), at(x, y, 1), at(x, y, 2)}; }
  void set_rgb(int x, int y, Rgb v) { at(x, y, 0) = v.r, at(x, y, 1) = v.g, at(x, y, 2) = v.b; }
};

}  // namespace obscura

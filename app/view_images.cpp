#include "view_images.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "obscura/io/image_codecs.h"
#include "obscura/io/image_codecs_loader.h"
#include "obscura/io/image_io.h"

namespace obscura::app {

namespace {

std::string png_of(const std::vector<uint8_t>& rgb, int width, int height) {
  EncodeRequest request;
  request.path = "frame.png";  // names the format and the image in messages; nothing is written
  request.width = width;
  request.height = height;
  request.channels = 3;
  request.stored = SampleType::kUint8;
  request.data_type = SampleType::kUint8;
  request.data = rgb.data();
  // Stored, not deflated: a frame travels once over loopback (the server listens on 127.0.0.1
  // only), where 700 KB of a 640 × 360 frame take about a millisecond, while deflating them at
  // zlib's fastest level costs 10–20 ms of the 50 ms a camera move may take.
  request.attributes.push_back({"png:compression", 0});
  const std::vector<unsigned char> bytes = image_codecs().encode(request);
  return std::string(bytes.begin(), bytes.end());
}

// A perceptually ordered ramp (dark blue, teal, green, yellow), linear between its stops.
std::array<uint8_t, 3> ramp(double t) {
  static constexpr std::array<std::array<double, 3>, 5> kStops = {{{0.27, 0.00, 0.33},
                                                                   {0.23, 0.32, 0.55},
                                                                   {0.13, 0.57, 0.55},
                                                                   {0.37, 0.79, 0.38},
                                                                   {0.99, 0.91, 0.14}}};
  t = std::clamp(t, 0.0, 1.0) * (kStops.size() - 1);
  const size_t i = std::min(size_t(t), kStops.size() - 2);
  const double f = t - double(i);
  std::array<uint8_t, 3> out{};
  for (int c = 0; c < 3; ++c)
    out[c] = uint8_t(std::lround(255 * (kStops[i][c] * (1 - f) + kStops[i + 1][c] * f)));
  return out;
}

}  // namespace

std::string beauty_png(const Image& linear, DisplaySettings display) {
  display.bits = std::min(display.bits, 8);
  const DisplayImage developed = develop(pixels_of(linear), display);
  std::vector<uint8_t> rgb(size_t(developed.width) * developed.height * 3);
  const int channels = developed.channels;
  for (size_t p = 0; p < size_t(developed.width) * developed.height; ++p)
    for (int c = 0; c < 3; ++c) rgb[3 * p + c] = uint8_t(developed.codes[p * channels + c]);
  return png_of(rgb, developed.width, developed.height);
}

std::string depth_png(const Image& depth, double* near_m, double* far_m) {
  double low = std::numeric_limits<double>::infinity(), high = 0;
  for (float z : depth.data)
    if (std::isfinite(z)) low = std::min(low, double(z)), high = std::max(high, double(z));
  if (!(low <= high)) low = high = 0;
  if (near_m) *near_m = low;
  if (far_m) *far_m = high;
  std::vector<uint8_t> rgb(size_t(depth.width) * depth.height * 3, 0);
  for (size_t p = 0; p < size_t(depth.width) * depth.height; ++p) {
    const float z = depth.data[p * depth.channels];
    if (!std::isfinite(z)) continue;
    const auto c = ramp(high > low ? (z - low) / (high - low) : 0);
    std::copy(c.begin(), c.end(), rgb.begin() + 3 * p);
  }
  return png_of(rgb, depth.width, depth.height);
}

std::string normal_png(const Image& normal) {
  std::vector<uint8_t> rgb(size_t(normal.width) * normal.height * 3, 0);
  for (size_t p = 0; p < size_t(normal.width) * normal.height; ++p) {
    const float* n = &normal.data[p * normal.channels];
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;  // nothing hit
    for (int c = 0; c < 3; ++c)
      rgb[3 * p + c] = uint8_t(std::lround(255 * std::clamp((n[c] + 1) * 0.5f, 0.f, 1.f)));
  }
  return png_of(rgb, normal.width, normal.height);
}

std::string id_png(const Image& id) {
  std::vector<uint8_t> rgb(size_t(id.width) * id.height * 3, 0);
  for (size_t p = 0; p < size_t(id.width) * id.height; ++p) {
    const float value = id.data[p * id.channels];
    if (!(value >= 0)) continue;
    // A hue per id from the golden ratio, so that neighbouring ids differ most.
    const double hue = std::fmod(double(value) * 0.6180339887498949 + 0.1, 1.0) * 6;
    const int sector = int(hue) % 6;
    const double f = hue - std::floor(hue);
    const double v = 0.95, s = 0.65, lo = v * (1 - s), down = v * (1 - s * f),
                 up = v * (1 - s * (1 - f));
    const double rgb_of[6][3] = {{v, up, lo},   {down, v, lo}, {lo, v, up},
                                 {lo, down, v}, {up, lo, v},   {v, lo, down}};
    for (int c = 0; c < 3; ++c) rgb[3 * p + c] = uint8_t(std::lround(255 * rgb_of[sector][c]));
  }
  return png_of(rgb, id.width, id.height);
}

}  // namespace obscura::app

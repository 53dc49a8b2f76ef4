#include "rgbe_codec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include "encode_attributes.h"
#include "obscura/math/error.h"

namespace obscura::codecs {

namespace {

constexpr size_t kMaxHeaderBytes = 64 * 1024;
constexpr int kMinRleWidth = 8, kMaxRleWidth = 32767;  // the adaptive form's range

class RgbeDecoder final : public StoredImageDecoder {
 public:
  explicit RgbeDecoder(EncodedBytes encoded) : encoded_(std::move(encoded)) {
    header_.format_name = "hdr";
    header_.format = SampleType::kFloat;
    header_.channels = 3;
    header_.channel_names = {"R", "G", "B"};
    read_header();
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw Error(encoded_.source, "cannot read image as hdr (Radiance RGBE): " + why);
  }

  // The next line (without its '\n'); fails past the header's bound or the end of the file.
  std::string_view next_line() {
    const auto bytes = encoded_.bytes;
    const size_t limit = std::min(bytes.size(), kMaxHeaderBytes);
    const auto* begin = reinterpret_cast<const char*>(bytes.data());
    for (size_t i = position_; i < limit; ++i)
      if (begin[i] == '\n') {
        std::string_view line(begin + position_, i - position_);
        position_ = i + 1;
        return line;
      }
    fail(bytes.size() > kMaxHeaderBytes ? "the header is longer than 64 KiB"
                                        : "the header is truncated");
  }

  void read_header() {
    std::string_view first = next_line();
    if (first.substr(0, 2) != "#?") fail("the file does not begin with #?RADIANCE");
    for (std::string_view line = next_line(); !line.empty(); line = next_line())
      if (line.substr(0, 7) == "FORMAT=" && line != "FORMAT=32-bit_rle_rgbe")
        fail("format '" + std::string(line.substr(7)) + "'; expected 32-bit_rle_rgbe");
    std::string resolution(next_line());
    char y_sign = 0, x_sign = 0;
    long height = 0, width = 0;
    int consumed = 0;
    if (std::sscanf(resolution.c_str(), "%cY %ld %cX %ld%n", &y_sign, &height, &x_sign, &width,
                    &consumed) != 4 ||
        size_t(consumed) != resolution.size() || (y_sign != '-' && y_sign != '+') ||
        x_sign != '+' || height <= 0 || width <= 0 || height > INT32_MAX || width > INT32_MAX)
      fail("resolution line '" + resolution + "'; expected '-Y height +X width'");
    header_.width = int(width);
    header_.height = int(height);
    bottom_up_ = y_sign == '+';
  }

  uint8_t next_byte() {
    if (position_ >= encoded_.bytes.size()) fail("the pixels are truncated");
    return encoded_.bytes[position_++];
  }

  // One scanline of width × (R, G, B, E) into `rgbe`.
  void read_scanline(uint8_t* rgbe) {
    const size_t width = size_t(header_.width);
    const auto bytes = encoded_.bytes;
    if (width >= kMinRleWidth && width <= kMaxRleWidth && bytes.size() - position_ >= 4 &&
        bytes[position_] == 2 && bytes[position_ + 1] == 2 && !(bytes[position_ + 2] & 0x80)) {
      size_t declared = size_t(bytes[position_ + 2]) << 8 | bytes[position_ + 3];
      if (declared != width) fail("a scanline's length is not the image's width");
      position_ += 4;
      for (size_t component = 0; component < 4; ++component)
        for (size_t x = 0; x < width;) {
          size_t count = next_byte();
          const bool run = count > 128;
          if (run) count -= 128;
          if (count == 0 || count > width - x) fail("a run overruns its scanline");
          if (run) {
            uint8_t value = next_byte();
            for (size_t i = 0; i < count; ++i) rgbe[4 * (x + i) + component] = value;
          } else {
            for (size_t i = 0; i < count; ++i) rgbe[4 * (x + i) + component] = next_byte();
          }
          x += count;
        }
      return;
    }
    // Flat pixels, where (1, 1, 1, n) repeats the previous pixel n times (n << 8 when
    // consecutive: the old run-length form).
    int shift = 0;
    for (size_t x = 0; x < width;) {
      uint8_t pixel[4];
      for (uint8_t& b : pixel) b = next_byte();
      if (pixel[0] == 1 && pixel[1] == 1 && pixel[2] == 1) {
        if (x == 0 || shift > 16) fail("a repeat has no pixel to repeat");
        size_t count = size_t(pixel[3]) << shift;
        if (count > width - x) fail("a repeat overruns its scanline");
        for (size_t i = 0; i < count; ++i, ++x) std::memcpy(rgbe + 4 * x, rgbe + 4 * (x - 1), 4);
        shift += 8;
      } else {
        std::memcpy(rgbe + 4 * x, pixel, 4);
        ++x;
        shift = 0;
      }
    }
  }

  void decode_stored(void* pixels) override {
    auto* out = static_cast<float*>(pixels);
    const size_t width = size_t(header_.width);
    std::vector<uint8_t> rgbe(width * 4);
    for (size_t row = 0; row < size_t(header_.height); ++row) {
      read_scanline(rgbe.data());
      const size_t y = bottom_up_ ? size_t(header_.height) - 1 - row : row;
      float* line = out + y * width * 3;
      for (size_t x = 0; x < width; ++x) {
        const uint8_t* p = &rgbe[4 * x];
        const float scale = p[3] == 0 ? 0.f : std::ldexp(1.f, int(p[3]) - 136);
        for (int c = 0; c < 3; ++c) line[3 * x + size_t(c)] = float(p[c]) * scale;
      }
    }
  }

  EncodedBytes encoded_;
  size_t position_ = 0;
  bool bottom_up_ = false;
};

// Ward's encoding: the largest channel v = m · 2^e with m in [0.5, 1) sets E = e + 128; each
// mantissa is channel · 256 / 2^e, truncated.
void to_rgbe(const float* rgb, uint8_t* out) {
  float c[3];
  for (int i = 0; i < 3; ++i) c[i] = rgb[i] > 0.f ? rgb[i] : 0.f;  // NaN and negatives: 0
  const double v = std::max({c[0], c[1], c[2]});
  if (v < 1e-32) {
    std::memset(out, 0, 4);
    return;
  }
  int e = 0;
  double scale = std::frexp(v, &e) * 256.0 / v;
  if (e > 127) {  // beyond RGBE's range: the largest value it holds
    std::memset(out, 255, 4);
    return;
  }
  for (int i = 0; i < 3; ++i) out[i] = uint8_t(std::min(255.0, double(c[i]) * scale));
  out[3] = uint8_t(e + 128);
}

// One component of a scanline in the adaptive run-length form: runs of 3 or more equal bytes
// as (128 + n, byte), up to 127; everything else as (n, n bytes), up to 128.
void write_component(const uint8_t* values, size_t count, std::vector<unsigned char>& out) {
  size_t x = 0;
  auto run_at = [&](size_t at) {
    size_t n = 1;
    while (at + n < count && n < 127 && values[at + n] == values[at]) ++n;
    return n;
  };
  while (x < count) {
    size_t run = run_at(x);
    if (run >= 3) {
      out.push_back(uint8_t(128 + run));
      out.push_back(values[x]);
      x += run;
      continue;
    }
    size_t literal_end = x;
    while (literal_end < count && literal_end - x < 128 && run_at(literal_end) < 3) ++literal_end;
    out.push_back(uint8_t(literal_end - x));
    out.insert(out.end(), values + x, values + literal_end);
    x = literal_end;
  }
}

}  // namespace

std::unique_ptr<ImageDecoder> open_rgbe(EncodedBytes encoded) {
  return std::make_unique<RgbeDecoder>(std::move(encoded));
}

std::vector<unsigned char> encode_rgbe(const EncodeRequest& request) {
  check_request(request, 4);
  std::vector<unsigned char> floats = request_pixels(request, SampleType::kFloat);
  const auto* data = reinterpret_cast<const float*>(floats.data());
  const size_t width = size_t(request.width), channels = size_t(request.channels);
  std::string head = "#?RADIANCE\n# Written by Obscura\nFORMAT=32-bit_rle_rgbe\n\n-Y " +
                     std::to_string(request.height) + " +X " + std::to_string(request.width) + "\n";
  std::vector<unsigned char> out(head.begin(), head.end());
  std::vector<uint8_t> rgbe(width * 4), component(width);
  for (size_t y = 0; y < size_t(request.height); ++y) {
    for (size_t x = 0; x < width; ++x) {
      const float* p = data + (y * width + x) * channels;
      const float rgb[3] = {p[0], p[channels >= 3 ? 1 : 0], p[channels >= 3 ? 2 : 0]};
      to_rgbe(rgb, &rgbe[4 * x]);
    }
    if (width < kMinRleWidth || width > kMaxRleWidth) {
      out.insert(out.end(), rgbe.begin(), rgbe.end());
      continue;
    }
    out.insert(out.end(), {2, 2, uint8_t(width >> 8), uint8_t(width & 0xff)});
    for (size_t c = 0; c < 4; ++c) {
      for (size_t x = 0; x < width; ++x) component[x] = rgbe[4 * x + c];
      write_component(component.data(), width, out);
    }
  }
  return out;
}

}  // namespace obscura::codecs

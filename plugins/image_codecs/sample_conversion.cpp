#include "sample_conversion.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "obscura/math/error.h"

namespace obscura::codecs {

namespace {

float to_float(SampleType type, const unsigned char* value) {
  switch (type) {
    case SampleType::kUint8:
      return float(*value) / 255.f;
    case SampleType::kUint16: {
      uint16_t v;
      std::memcpy(&v, value, 2);
      return float(v) / 65535.f;
    }
    case SampleType::kHalf: {
      Imath::half h;
      std::memcpy(&h, value, 2);
      return float(h);
    }
    case SampleType::kFloat:
    case SampleType::kOther:
      break;
  }
  float f;
  std::memcpy(&f, value, 4);
  return f;
}

// [0, 1] to 0…largest, rounded; NaN to 0.
template <typename Int>
Int quantize(float f, float largest) {
  if (!(f > 0.f)) return 0;
  if (f >= 1.f) return Int(largest);
  return Int(f * largest + 0.5f);
}

void from_float(float f, SampleType type, unsigned char* out) {
  switch (type) {
    case SampleType::kUint8:
      *out = quantize<uint8_t>(f, 255.f);
      return;
    case SampleType::kUint16: {
      uint16_t v = quantize<uint16_t>(f, 65535.f);
      std::memcpy(out, &v, 2);
      return;
    }
    case SampleType::kHalf: {
      Imath::half h(f);
      std::memcpy(out, &h, 2);
      return;
    }
    case SampleType::kFloat:
    case SampleType::kOther:
      break;
  }
  std::memcpy(out, &f, 4);
}

}  // namespace

size_t sample_size(SampleType type) {
  switch (type) {
    case SampleType::kUint8:
      return 1;
    case SampleType::kUint16:
    case SampleType::kHalf:
      return 2;
    case SampleType::kFloat:
      return 4;
    case SampleType::kOther:
      break;
  }
  return 0;
}

void convert_samples(SampleType from, const void* in, SampleType to, void* out, size_t count) {
  if (from == SampleType::kOther || to == SampleType::kOther)
    throw Error("image codecs: no conversion for this sample type");
  if (from == to) {
    std::memcpy(out, in, count * sample_size(from));
    return;
  }
  const auto* src = static_cast<const unsigned char*>(in);
  auto* dst = static_cast<unsigned char*>(out);
  const size_t in_size = sample_size(from), out_size = sample_size(to);
  // Integer to integer exactly (8 → 16 bits: × 257), as the values' [0, 1] meaning requires.
  if (from == SampleType::kUint8 && to == SampleType::kUint16) {
    for (size_t i = 0; i < count; ++i) {
      uint16_t v = uint16_t(src[i] * 257);
      std::memcpy(dst + 2 * i, &v, 2);
    }
    return;
  }
  for (size_t i = 0; i < count; ++i)
    from_float(to_float(from, src + i * in_size), to, dst + i * out_size);
}

void convert_pixels(SampleType from, const void* in, int stored_channels, SampleType to, void* out,
                    int channels, size_t pixel_count) {
  if (stored_channels == channels) {
    convert_samples(from, in, to, out, pixel_count * size_t(channels));
    return;
  }
  const size_t in_pixel = sample_size(from) * size_t(stored_channels);
  const size_t out_pixel = sample_size(to) * size_t(channels);
  const auto* src = static_cast<const unsigned char*>(in);
  auto* dst = static_cast<unsigned char*>(out);
  for (size_t p = 0; p < pixel_count; ++p)
    convert_samples(from, src + p * in_pixel, to, dst + p * out_pixel, size_t(channels));
}

}  // namespace obscura::codecs

#include "obscura/scene/texture.h"

#include <array>
#include <cmath>

#include "obscura/color/srgb.h"
#include "obscura/math/safe_index.h"

namespace obscura {

int wrap_texel_index(int i, int size, TextureWrap wrap) {
  // Every mode leaves an index inside the texture as it is: most lookups, and no division.
  if (unsigned(i) < unsigned(size)) return i;
  switch (wrap) {
    case TextureWrap::kClampToEdge:
      return i < 0 ? 0 : (i >= size ? size - 1 : i);
    case TextureWrap::kMirroredRepeat: {
      int period = 2 * size;
      int m = ((i % period) + period) % period;
      return m < size ? m : period - 1 - m;
    }
    case TextureWrap::kRepeat:
    default:
      return ((i % size) + size) % size;
  }
}

namespace {

// srgb_decode of every 8-bit value, as texel() scales it. An 8-bit channel has only 256 values,
// so a lookup replaces the pow() per channel per texel (12 per bilinear lookup, a visible part of
// the tracer's cost per sample) with exactly the same floats.
const std::array<float, 256>& srgb_decode_8bit() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t;
    for (int i = 0; i < 256; ++i) t[i] = srgb_decode(uint8_t(i) * (1.f / 255.f));
    return t;
  }();
  return table;
}

// The linear RGBA value of one texel.
Vector4f texel_rgba(const Texture& t, int x, int y) {
  float v[4] = {0, 0, 0, 1};
  if (t.encoding == TextureEncoding::kSrgb && !t.texels_8bit.empty()) {
    // The same values as the general path below, colour channels through the table.
    const std::array<float, 256>& decode = srgb_decode_8bit();
    const uint8_t* p = &t.texels_8bit[(size_t(y) * t.width + x) * t.channels];
    if (t.channels <= 2) {  // grey (+ alpha)
      v[0] = v[1] = v[2] = decode[p[0]];
      if (t.channels == 2) v[3] = p[1] * (1.f / 255.f);
    } else {
      for (int c = 0; c < 3; ++c) v[c] = decode[p[c]];
      if (t.channels >= 4) v[3] = p[3] * (1.f / 255.f);
    }
    return {v[0], v[1], v[2], v[3]};
  }
  for (int c = 0; c < t.channels && c < 4; ++c) v[c] = t.texel(x, y, c);
  if (t.channels == 1 || t.channels == 2) {  // grey (+ alpha)
    if (t.channels == 2) v[3] = v[1];
    v[1] = v[2] = v[0];
  }
  if (t.encoding == TextureEncoding::kSrgb)
    for (int c = 0; c < 3; ++c) v[c] = srgb_decode(v[c]);
  return {v[0], v[1], v[2], v[3]};
}

}  // namespace

UvTransform UvTransform::offset_rotation_scale(Point2f offset, float rotation, Point2f scale) {
  const float c = std::cos(rotation), s = std::sin(rotation);
  UvTransform t;
  t.m00 = c * scale.x, t.m01 = s * scale.y, t.m02 = offset.x;
  t.m10 = -s * scale.x, t.m11 = c * scale.y, t.m12 = offset.y;
  return t;
}

Vector4f sample_texture(const Texture& t, Point2f uv) {
  if (t.width <= 0 || t.height <= 0) return {0, 0, 0, 1};
  // Continuous texel coordinates, texel centres at integer + ½.
  float x = uv.x * t.width, y = uv.y * t.height;
  if (t.filter == TextureFilter::kNearest) {
    int ix = wrap_texel_index(floor_to_index(x), t.width, t.wrap_u);
    int iy = wrap_texel_index(floor_to_index(y), t.height, t.wrap_v);
    return texel_rgba(t, ix, iy);
  }
  float fx = x - 0.5f, fy = y - 0.5f;
  // NaN-safe (math/safe_index.h): a NaN or huge uv reads a texel inside the texture.
  int x0 = floor_to_index(fx), y0 = floor_to_index(fy);
  float ax = clamp_or_low(fx - std::floor(fx), 0.f, 1.f),
        ay = clamp_or_low(fy - std::floor(fy), 0.f, 1.f);
  // The two columns and rows, each wrapped once rather than once per texel.
  const int xs[2] = {wrap_texel_index(x0, t.width, t.wrap_u),
                     wrap_texel_index(x0 + 1, t.width, t.wrap_u)};
  const int ys[2] = {wrap_texel_index(y0, t.height, t.wrap_v),
                     wrap_texel_index(y0 + 1, t.height, t.wrap_v)};
  Vector4f result;
  if (t.encoding == TextureEncoding::kSrgb && t.channels >= 3 && !t.texels_8bit.empty()) {
    // The common colour texture (8-bit sRGB, RGB or RGBA) without texel_rgba's per-texel
    // branches: the same values, summed in the same order.
    const std::array<float, 256>& decode = srgb_decode_8bit();
    const uint8_t* texels = t.texels_8bit.data();
    const bool has_alpha = t.channels >= 4;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        float w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
        if (w == 0) continue;
        const uint8_t* p = texels + (size_t(ys[dy]) * t.width + xs[dx]) * t.channels;
        Vector4f v(decode[p[0]], decode[p[1]], decode[p[2]],
                   has_alpha ? p[3] * (1.f / 255.f) : 1.f);
        result = result + v * w;
      }
    return result;
  }
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      float w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
      if (w == 0) continue;
      result = result + texel_rgba(t, xs[dx], ys[dy]) * w;
    }
  return result;
}

}  // namespace obscura

#include "obscura/raster/texture.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "obscura/math/error.h"
#include "obscura/math/safe_index.h"

namespace obscura::raster {

Texture::Texture(const Image& image, TextureWrap wrap_u, TextureWrap wrap_v)
    : wrap_u_(wrap_u), wrap_v_(wrap_v) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 3)
    throw Error("texture", "expected a non-empty RGB or RGBA image");
  Level base{image.width, image.height, {}};
  base.texels.resize(size_t(image.width) * image.height);
  // Rows in parallel, each texel computed as alone (the same values for any thread count).
  tbb::parallel_for(0, image.height, [&](int y) {
    for (int x = 0; x < image.width; ++x)
      base.texels[size_t(y) * image.width + x] = image.rgb(x, y);
  });
  levels_.push_back(std::move(base));
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& src = levels_.back();
    Level dst{std::max(1, src.width / 2), std::max(1, src.height / 2), {}};
    dst.texels.resize(size_t(dst.width) * dst.height);
    tbb::parallel_for(0, dst.height, [&](int y) {
      for (int x = 0; x < dst.width; ++x) {
        // The source texels whose centres fall in this texel's footprint.
        int x0 = x * src.width / dst.width, x1 = (x + 1) * src.width / dst.width;
        int y0 = y * src.height / dst.height, y1 = (y + 1) * src.height / dst.height;
        Rgb sum;
        for (int j = y0; j < y1; ++j)
          for (int i = x0; i < x1; ++i) sum += src.texels[size_t(j) * src.width + i];
        dst.texels[size_t(y) * dst.width + x] = sum / float((x1 - x0) * (y1 - y0));
      }
    });
    levels_.push_back(std::move(dst));
  }
}

Rgb Texture::texel(int level, int i, int j) const {
  const Level& l = levels_[level];
  return l.texels[size_t(wrap_texel_index(j, l.height, wrap_v_)) * l.width +
                  wrap_texel_index(i, l.width, wrap_u_)];
}

Rgb Texture::sample_nearest(float u, float v) const {
  return texel(0, floor_to_index(u * width()), floor_to_index(v * height()));
}

Rgb Texture::sample_bilinear(float u, float v, int level) const {
  level = std::clamp(level, 0, levels() - 1);
  float x = u * width(level) - 0.5f, y = v * height(level) - 0.5f;
  // NaN-safe (math/safe_index.h); a NaN weight then blends NaN, never reads outside.
  int i = floor_to_index(x), j = floor_to_index(y);
  float tx = clamp_or_low(x - std::floor(x), 0.f, 1.f),
        ty = clamp_or_low(y - std::floor(y), 0.f, 1.f);
  return (texel(level, i, j) * (1 - tx) + texel(level, i + 1, j) * tx) * (1 - ty) +
         (texel(level, i, j + 1) * (1 - tx) + texel(level, i + 1, j + 1) * tx) * ty;
}

Rgb Texture::sample_trilinear(float u, float v, float du_dx, float dv_dx, float du_dy,
                              float dv_dy) const {
  float w = float(width()), h = float(height());
  float rho = std::max(std::hypot(du_dx * w, dv_dx * h), std::hypot(du_dy * w, dv_dy * h));
  float lambda = rho > 0 ? std::log2(rho) : 0.f;
  if (!(lambda > 0)) return sample_bilinear(u, v, 0);  // NaN too: int(NaN) is undefined
  if (lambda >= float(levels() - 1)) return sample_bilinear(u, v, levels() - 1);
  int lo = int(lambda);
  float t = lambda - float(lo);
  return sample_bilinear(u, v, lo) * (1 - t) + sample_bilinear(u, v, lo + 1) * t;
}

Rgb Texture::sample(TextureFilter filter, float u, float v, float du_dx, float dv_dx, float du_dy,
                    float dv_dy) const {
  switch (filter) {
    case TextureFilter::kNearest:
      return sample_nearest(u, v);
    case TextureFilter::kBilinear:
      return sample_bilinear(u, v, 0);
    case TextureFilter::kTrilinear:
      return sample_trilinear(u, v, du_dx, dv_dx, du_dy, dv_dy);
  }
  return {};
}

}  // namespace obscura::raster

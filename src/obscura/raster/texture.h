// A mipmapped RGB texture with bilinear and trilinear filtering.
//
// Texture coordinates follow glTF: (0, 0) is the top-left corner of the image, u to the right,
// v down, and texel (i, j) has its centre at ((i + ½)/width, (j + ½)/height). Coordinates wrap
// per axis as the scene texture's sampler says (repeat, mirrored repeat, clamp to edge). Level k of
// the pyramid halves level k−1 with a box filter (odd sizes round down, with the last row/column
// folded in), down to 1×1.
#pragma once

#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/scene/texture.h"

namespace obscura::raster {

enum class TextureFilter { kNearest, kBilinear, kTrilinear };

class Texture {
 public:
  // From a linear RGB(A) image (alpha ignored). Throws obscura::Error for an empty image.
  explicit Texture(const Image& linear_rgb, TextureWrap wrap_u = TextureWrap::kRepeat,
                   TextureWrap wrap_v = TextureWrap::kRepeat);

  int levels() const { return int(levels_.size()); }
  int width(int level = 0) const { return levels_[level].width; }
  int height(int level = 0) const { return levels_[level].height; }
  Rgb texel(int level, int i, int j) const;  // wraps i, j per the wrap modes

  Rgb sample_nearest(float u, float v) const;
  Rgb sample_bilinear(float u, float v, int level = 0) const;
  // Trilinear: the level of detail comes from the screen-space derivatives of (u, v): the
  // footprint's longer side in texels, ρ, gives λ = log2 ρ, blended between ⌊λ⌋ and ⌈λ⌉.
  Rgb sample_trilinear(float u, float v, float du_dx, float dv_dx, float du_dy, float dv_dy) const;
  Rgb sample(TextureFilter filter, float u, float v, float du_dx, float dv_dx, float du_dy,
             float dv_dy) const;

 private:
  struct Level {
    int width, height;
    std::vector<Rgb> texels;
  };
  std::vector<Level> levels_;
  TextureWrap wrap_u_, wrap_v_;
};

}  // namespace obscura::raster

// The film: what renderers write to. Linear, scene-referred RGB (Rec.709 primaries) with the sum
// of sample weights per pixel, so that a pixel's value is Σ wᵢ·Lᵢ / Σ wᵢ.
//
// Renderers fill the film tile by tile in parallel (see tiles.h); tiles do not overlap, so two
// threads never write the same pixel and no locking is needed.
#pragma once

#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/film/image.h"
#include "obscura/math/bounds.h"
#include "obscura/math/vector.h"

namespace obscura {

class Film {
 public:
  // Precondition: width > 0 and height > 0 (throws obscura::Error otherwise).
  Film(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  Bounds2i bounds() const { return {{0, 0}, {width_, height_}}; }

  void add_sample(Point2i pixel, Rgb radiance, float weight = 1.f) {
    Pixel& p = pixels_[index(pixel)];
    p.weighted_sum += radiance * weight;
    p.weight_sum += weight;
  }

  // The weighted mean of a pixel's samples; black for a pixel that received none. Weights may be
  // negative (filters with negative lobes), and so, with few samples, may their sum.
  Rgb pixel(Point2i p) const {
    const Pixel& px = pixels_[index(p)];
    return px.weight_sum != 0 ? px.weighted_sum / px.weight_sum : Rgb();
  }
  float weight(Point2i p) const { return pixels_[index(p)].weight_sum; }
  // Multiplies a pixel's light (not its weight) by `factor`: a gain applied after rendering.
  void scale_pixel(Point2i pixel, float factor) {
    Pixel& p = pixels_[index(pixel)];
    p.weighted_sum = p.weighted_sum * factor;
  }

  // The film as a linear RGB image.
  Image to_image() const;

  // The film's sums exactly as held: Σ w·L as channels R, G, B and Σ w as W. What a process that
  // rendered part of a frame hands over, and from_sums() takes back, bit for bit.
  Image sums() const;
  // Throws obscura::Error unless `sums` has 4 channels and a positive size.
  static Film from_sums(const Image& sums);

 private:
  struct Pixel {
    Rgb weighted_sum;
    float weight_sum = 0;
  };
  size_t index(Point2i p) const { return size_t(p.y) * width_ + p.x; }

  int width_, height_;
  std::vector<Pixel> pixels_;
};

}  // namespace obscura

#include "obscura/raster/render_target.h"

#include <algorithm>
#include <limits>
#include <string>

#include <tbb/parallel_for.h>

#include "obscura/math/error.h"
#include "obscura/raster/msaa.h"

namespace obscura::raster {

RenderTarget::RenderTarget(int width, int height, int samples, bool aovs)
    : width_(width),
      height_(height),
      samples_(samples),
      stride_((width + kRowAlignment - 1) / kRowAlignment * kRowAlignment),
      aovs_(aovs) {
  if (width <= 0 || height <= 0)
    throw Error("render target", "size must be positive; got " + std::to_string(width) + "x" +
                                     std::to_string(height));
  if (!is_valid_sample_count(samples))
    throw Error("render target", "MSAA samples must be 1, 4 or 8; got " + std::to_string(samples));
  size_t n = size_t(stride_) * height * samples;
  color_.resize(3 * n);  // n is a multiple of kRowAlignment, the row stride being one
  depth_.resize(n, 1.f);
  if (aovs) {
    object_id_.resize(n, kNoObject);
    primitive_id_.resize(n, 0);
    view_depth_.resize(n, std::numeric_limits<float>::infinity());
    normal_.resize(n);
  }
}

void RenderTarget::set_share(int part, int parts) {
  if (parts < 1 || part < 0 || part >= parts)
    throw Error("render target", "part " + std::to_string(part) + " of " + std::to_string(parts) +
                                     " does not exist");
  share_part_ = part;
  share_parts_ = parts;
}

// In parallel over bands of elements: a 1080p frame's colour and depth are 33 MB, which one
// thread takes milliseconds to write while the others wait for the draw to start.
void RenderTarget::clear(Rgb color, float depth) {
  const size_t elements = depth_.size();  // samples, one group of kRowAlignment at a time
  constexpr size_t kBand = 64 * 1024;     // elements; a multiple of kRowAlignment
  tbb::parallel_for(size_t(0), (elements + kBand - 1) / kBand, [&](size_t band) {
    const size_t first = band * kBand, last = std::min(elements, first + kBand);
    for (size_t g = first * 3; g < last * 3; g += 3 * kRowAlignment) {
      std::fill_n(color_.begin() + g, kRowAlignment, color.r);
      std::fill_n(color_.begin() + g + kRowAlignment, kRowAlignment, color.g);
      std::fill_n(color_.begin() + g + 2 * kRowAlignment, kRowAlignment, color.b);
    }
    std::fill(depth_.begin() + first, depth_.begin() + last, depth);
    if (aovs_) {
      std::fill(object_id_.begin() + first, object_id_.begin() + last, kNoObject);
      std::fill(primitive_id_.begin() + first, primitive_id_.begin() + last, 0u);
      std::fill(view_depth_.begin() + first, view_depth_.begin() + last,
                std::numeric_limits<float>::infinity());
      std::fill(normal_.begin() + first, normal_.begin() + last, Vector3f());
    }
  });
}

Image RenderTarget::resolve_color() const {
  Image image(width_, height_, 3);
  const float inv = 1.f / float(samples_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      Rgb sum;
      for (int s = 0; s < samples_; ++s) sum += color(sample_index(x, y, s));
      image.set_rgb(x, y, sum * inv);
    }
  return image;
}

void RenderTarget::accumulate_into(Film& film, float weight) const {
  accumulate(film, weight, nullptr);
}

void RenderTarget::accumulate_into(Film& film, const std::vector<float>& gain) const {
  if (gain.size() != size_t(width_) * size_t(height_))
    throw Error("render target", "gain for " + std::to_string(gain.size()) +
                                     " pixels; the target has " + std::to_string(width_) + "x" +
                                     std::to_string(height_));
  accumulate(film, 1.f, gain.data());
}

void RenderTarget::accumulate(Film& film, float weight, const float* gain) const {
  if (film.width() != width_ || film.height() != height_)
    throw Error("render target", "film size " + std::to_string(film.width()) + "x" +
                                     std::to_string(film.height()) + " differs from " +
                                     std::to_string(width_) + "x" + std::to_string(height_));
  // Rows in parallel: each pixel's sum is its own, so the film is the same for any thread count.
  const float inv = 1.f / float(samples_);
  tbb::parallel_for(0, height_, [&](int y) {
    for (int x = 0; x < width_; ++x) {
      if (!draws_pixel(x, y)) continue;
      Rgb sum;
      for (int s = 0; s < samples_; ++s) sum += color(sample_index(x, y, s));
      const float scale = gain ? inv * gain[size_t(y) * size_t(width_) + size_t(x)] : inv;
      film.add_sample({x, y}, sum * scale, weight);
    }
  });
}

Image RenderTarget::depth_image() const {
  Image image(width_, height_, 1);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) image.at(x, y, 0) = depth_[sample_index(x, y)];
  return image;
}

Image RenderTarget::view_depth_image() const {
  if (!aovs_) throw Error("render target", "view depth needs a render target with aovs on");
  Image image(width_, height_, 1);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) image.at(x, y, 0) = view_depth_[sample_index(x, y)];
  return image;
}

Image RenderTarget::normal_image() const {
  if (!aovs_) throw Error("render target", "normals need a render target with aovs on");
  Image image(width_, height_, 3);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      Vector3f n = normal_[sample_index(x, y)];
      image.set_rgb(x, y, {n.x, n.y, n.z});
    }
  return image;
}

}  // namespace obscura::raster

#include "obscura/film/aov_buffers.h"

#include <limits>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

AovBuffers::AovBuffers(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0)
    throw Error("AOV buffers", "need a positive size; got " + std::to_string(width) + "x" +
                                   std::to_string(height));
  pixels_.resize(size_t(width) * height);
}

void AovBuffers::add_sample(Point2i pixel, bool hit, Rgb albedo, Normal3f normal, float depth,
                            uint32_t id) {
  Pixel& p = pixels_[size_t(pixel.y) * width_ + pixel.x];
  ++p.samples;
  if (!hit) return;
  ++p.hits;
  p.albedo += albedo;
  p.normal += to_vector(normal);
  p.depth += depth;
  if (p.id < 0) p.id = int32_t(id);
}

Image AovBuffers::albedo() const {
  Image image(width_, height_, 3);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Pixel& p = pixels_[size_t(y) * width_ + x];
      image.set_rgb(x, y, p.samples > 0 ? p.albedo / float(p.samples) : Rgb());
    }
  return image;
}

Image AovBuffers::normal() const {
  Image image(width_, height_, 3);
  image.channel_names = {"X", "Y", "Z"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      Vector3f n = pixels_[size_t(y) * width_ + x].normal;
      float len = length(n);
      if (len > 0) n = n / len;
      image.set_rgb(x, y, {n.x, n.y, n.z});
    }
  return image;
}

Image AovBuffers::depth() const {
  Image image(width_, height_, 1);
  image.channel_names = {"Z"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Pixel& p = pixels_[size_t(y) * width_ + x];
      image.at(x, y, 0) =
          p.hits > 0 ? float(p.depth / p.hits) : std::numeric_limits<float>::infinity();
    }
  return image;
}

Image AovBuffers::id() const {
  Image image(width_, height_, 1);
  image.channel_names = {"id"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) image.at(x, y, 0) = float(pixels_[size_t(y) * width_ + x].id);
  return image;
}

}  // namespace obscura

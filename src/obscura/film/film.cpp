#include "obscura/film/film.h"

#include <string>

#include "obscura/math/error.h"

namespace obscura {

Film::Film(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0)
    throw Error("film resolution must be positive; got " + std::to_string(width) + "x" +
                std::to_string(height));
  pixels_.resize(size_t(width) * height);
}

Image Film::to_image() const {
  Image image(width_, height_, 3);
  image.channel_names = {"R", "G", "B"};
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) image.set_rgb(x, y, pixel({x, y}));
  return image;
}

Image Film::sums() const {
  Image image(width_, height_, 4);
  image.channel_names = {"R", "G", "B", "W"};
  float* out = image.data.data();
  for (const Pixel& p : pixels_) {
    *out++ = p.weighted_sum.r, *out++ = p.weighted_sum.g, *out++ = p.weighted_sum.b;
    *out++ = p.weight_sum;
  }
  return image;
}

Film Film::from_sums(const Image& sums) {
  if (sums.channels != 4)
    throw Error("film sums", "need 4 channels (R, G, B, W); got " + std::to_string(sums.channels));
  Film film(sums.width, sums.height);
  const float* in = sums.data.data();
  for (Pixel& p : film.pixels_) {
    p.weighted_sum = {in[0], in[1], in[2]};
    p.weight_sum = in[3];
    in += 4;
  }
  return film;
}

}  // namespace obscura

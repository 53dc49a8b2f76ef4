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

}  // namespace obscura

#include "obscura/film/work_share.h"

#include <algorithm>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// Calls f(x0, x1, y) for every run of owned pixels of row y, in row-major order.
template <class F>
void for_each_owned_run(const TileDeal& deal, int part, F&& f) {
  const int columns = deal.columns();
  for (int y = 0; y < deal.height; ++y) {
    const int row_tile = (y / deal.tile_size) * columns;
    for (int column = 0; column < columns; ++column)
      if (deal.owner_of_tile(row_tile + column) == part)
        f(column * deal.tile_size, std::min(deal.width, (column + 1) * deal.tile_size), y);
  }
}

void check_image(const TileDeal& deal, const Image& image) {
  if (image.width != deal.width || image.height != deal.height)
    throw Error("work share", "an image of " + std::to_string(image.width) + "x" +
                                  std::to_string(image.height) + " where the frame is " +
                                  std::to_string(deal.width) + "x" + std::to_string(deal.height));
}

}  // namespace

size_t TileDeal::pixel_count(int part) const {
  size_t count = 0;
  for_each_owned_run(*this, part, [&](int x0, int x1, int) { count += size_t(x1 - x0); });
  return count;
}

std::vector<float> pack_owned_pixels(const TileDeal& deal, int part, const Image& image) {
  check_image(deal, image);
  std::vector<float> packed;
  packed.reserve(deal.pixel_count(part) * size_t(image.channels));
  for_each_owned_run(deal, part, [&](int x0, int x1, int y) {
    auto row = image.data.begin() + (size_t(y) * image.width) * image.channels;
    packed.insert(packed.end(), row + size_t(x0) * image.channels,
                  row + size_t(x1) * image.channels);
  });
  return packed;
}

void unpack_owned_pixels(const TileDeal& deal, int part, const std::vector<float>& packed,
                         Image& image) {
  check_image(deal, image);
  const size_t expected = deal.pixel_count(part) * size_t(image.channels);
  if (packed.size() != expected)
    throw Error("work share", "part " + std::to_string(part) + " sent " +
                                  std::to_string(packed.size()) + " values; its pixels need " +
                                  std::to_string(expected));
  auto next = packed.begin();
  for_each_owned_run(deal, part, [&](int x0, int x1, int y) {
    const size_t count = size_t(x1 - x0) * image.channels;
    std::copy_n(next, count, image.data.begin() + (size_t(y) * image.width + x0) * image.channels);
    next += std::ptrdiff_t(count);
  });
}

}  // namespace obscura

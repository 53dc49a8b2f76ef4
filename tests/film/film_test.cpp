#include "obscura/film/film.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "obscura/film/tiles.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(Film, PixelIsTheWeightedMeanOfItsSamples) {
  Film film(4, 3);
  film.add_sample({1, 2}, Rgb(1, 2, 3), 1.f);
  film.add_sample({1, 2}, Rgb(3, 2, 1), 3.f);
  Rgb p = film.pixel({1, 2});
  EXPECT_FLOAT_EQ(p.r, (1 + 9) / 4.f);
  EXPECT_FLOAT_EQ(p.g, 2.f);
  EXPECT_FLOAT_EQ(p.b, (3 + 3) / 4.f);
  EXPECT_FLOAT_EQ(film.weight({1, 2}), 4.f);
  EXPECT_EQ(film.pixel({0, 0}), Rgb());  // no samples: black, not NaN
  Image image = film.to_image();
  EXPECT_EQ(image.width, 4);
  EXPECT_EQ(image.height, 3);
  EXPECT_FLOAT_EQ(image.at(1, 2, 0), 2.5f);
}

TEST(Film, RejectsEmptyResolution) {
  EXPECT_THROW(Film(0, 10), Error);
  EXPECT_THROW(Film(10, -1), Error);
}

TEST(Tiles, CoverTheRegionExactlyOnce) {
  Bounds2i region{{3, 5}, {70, 41}};
  std::vector<int> covered(100 * 100, 0);
  for (const Bounds2i& t : make_tiles(region, 16))
    for (int y = t.min.y; y < t.max.y; ++y)
      for (int x = t.min.x; x < t.max.x; ++x) ++covered[y * 100 + x];
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) {
      bool inside = x >= 3 && x < 70 && y >= 5 && y < 41;
      ASSERT_EQ(covered[y * 100 + x], inside ? 1 : 0) << x << "," << y;
    }
}

TEST(Tiles, ParallelRunVisitsEveryTileAndReportsProgressInOrder) {
  Bounds2i region{{0, 0}, {100, 60}};
  std::atomic<long> pixels{0};
  std::vector<int> reported;
  for_each_tile_parallel(
      region, 16, [&](const Bounds2i& t) { pixels += t.area(); },
      [&](int done, int total) {
        EXPECT_EQ(total, 7 * 4);
        reported.push_back(done);
      });
  EXPECT_EQ(pixels.load(), 6000);
  ASSERT_EQ(reported.size(), 28u);
  for (size_t i = 0; i < reported.size(); ++i) EXPECT_EQ(reported[i], int(i) + 1);
}

}  // namespace
}  // namespace obscura

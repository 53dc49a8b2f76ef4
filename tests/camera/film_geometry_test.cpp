// Film geometry: crop windows in pixels, and bad input.
#include "obscura/camera/film_geometry.h"

#include <gtest/gtest.h>

#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(FilmGeometry, CropWindowCoversTheRegionsPixels) {
  FilmGeometry film;
  film.width_px = 200;
  film.height_px = 100;
  film.crop = {.x_min = 0.25, .y_min = 0.5, .x_max = 0.75, .y_max = 1};
  Bounds2i b = film.crop_pixels();
  EXPECT_EQ(b.min.x, 50);
  EXPECT_EQ(b.min.y, 50);
  EXPECT_EQ(b.max.x, 150);
  EXPECT_EQ(b.max.y, 100);
  // Fractions between pixels round up on both sides, so neighbouring crops tile the image.
  film.crop = {.x_min = 0.101, .y_min = 0, .x_max = 0.499, .y_max = 1};
  b = film.crop_pixels();
  EXPECT_EQ(b.min.x, 21);
  EXPECT_EQ(b.max.x, 100);
}

TEST(FilmGeometry, RejectsBadInputNamingIt) {
  auto message = [](FilmGeometry f) -> std::string {
    try {
      validate(f);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  FilmGeometry f;
  f.width_px = 0;
  EXPECT_NE(message(f).find("resolution: must be positive; got 0x512"), std::string::npos);
  f = {};
  f.crop = {.x_min = -0.1, .y_min = 0, .x_max = 1, .y_max = 1};
  EXPECT_NE(message(f).find("crop: must lie within [0, 1]"), std::string::npos);
  f.crop = {.x_min = 0, .y_min = 0, .x_max = 1.5, .y_max = 1};
  EXPECT_NE(message(f).find("1.5"), std::string::npos);
  f.crop = {.x_min = 0.5, .y_min = 0, .x_max = 0.5, .y_max = 1};
  EXPECT_NE(message(f).find("at least one pixel"), std::string::npos);
  f = {};
  f.pixel_aspect = 0;
  EXPECT_NE(message(f).find("pixel_aspect"), std::string::npos);
}

}  // namespace
}  // namespace obscura

// The thin lens's relative illumination as the tracer renders it: a wide camera facing a uniform
// emitter gives pixel values that fall off as cos⁴θ (θ the field angle, computed here from the
// field of view), the image centre keeps its exposure, and the lens barrel darkens the corners
// below cos⁴. The rasterizer's gain gives the same numbers.
#include <cmath>
#include <memory>
#include <numbers>

#include <gtest/gtest.h>

#include "obscura/raster/vignetting_gain.h"
#include "obscura/scene/scene.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSize = 48;
constexpr double kFovDegrees = 100;  // vertical = horizontal on a square image

Scene emitter_scene() {
  Scene scene;
  scene.name = "wall";
  Material emitter;
  emitter.name = "emitter";
  emitter.model = EmissiveMaterial{};
  emitter.emission = Rgb(1);
  scene.materials = {emitter};
  Mesh wall;
  wall.name = "wall";
  wall.positions = {{-50, -50, -1}, {50, -50, -1}, {50, 50, -1}, {-50, 50, -1}};
  wall.indices = {0, 1, 2, 0, 2, 3};
  scene.add_mesh(wall);
  Camera& c = scene.camera;
  c.projection = Perspective::from_vertical_fov_degrees(kFovDegrees);
  c.film.width_px = kSize;
  c.film.height_px = kSize;
  return scene;
}

Image render_image(const Scene& scene, int spp = 16) {
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film film(scene.camera.film.width_px, scene.camera.film.height_px);
  render(trace, scene.camera, DirectLightingIntegrator(), {.samples_per_pixel = spp, .seed = 1},
         film);
  return film.to_image();
}

// cos⁴ of the field angle averaged over pixel (x, y): the window point of a square image with
// this field of view is ((2u/W − 1), (1 − 2v/H))·tan(FOV/2), and tanθ its length.
double mean_cos4(int x, int y) {
  const double half = std::tan(0.5 * kFovDegrees * kPi / 180);
  double sum = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      double wx = (2 * (x + (i + 0.5) / 8) / kSize - 1) * half;
      double wy = (1 - 2 * (y + (j + 0.5) / 8) / kSize) * half;
      double cos2 = 1 / (1 + wx * wx + wy * wy);
      sum += cos2 * cos2;
    }
  return sum / 64;
}

TEST(VignettingRender, NaturalVignettingFallsOffAsCosineToTheFourth) {
  Scene scene = emitter_scene();
  scene.camera.lens.vignetting.natural = true;
  for (bool depth_of_field : {false, true}) {
    scene.camera.lens.depth_of_field = depth_of_field;
    scene.camera.lens.f_number = 2.8;
    scene.camera.lens.focus_distance_m = 1;
    scene.camera.lens.focus_breathing = false;  // the field of view the reference assumes
    Image image = render_image(scene);
    // The centre, then along the diagonal out to the corner (field angles 0° to ~59°).
    for (int k : {0, 6, 12, 18, 23}) {
      int x = kSize / 2 + k, y = kSize / 2 + k;
      if (x >= kSize) continue;
      double expected = mean_cos4(x, y);
      EXPECT_NEAR(image.at(x, y, 1), expected, 0.01 * expected)
          << "pixel " << x << "," << y << (depth_of_field ? " with" : " without")
          << " depth of field";
    }
    EXPECT_NEAR(image.at(kSize - 1, kSize / 2, 0), mean_cos4(kSize - 1, kSize / 2), 0.01);
  }
}

TEST(VignettingRender, BarrelDarkensTheCornersBelowCosineToTheFourthAndKeepsTheCentre) {
  Scene scene = emitter_scene();
  Camera& c = scene.camera;
  c.lens.depth_of_field = true;
  c.lens.f_number = 2;
  c.lens.focus_distance_m = 1;
  c.lens.vignetting.natural = true;
  Image natural = render_image(scene, 64);
  const double focal = c.focal_length_mm(), aperture = focal / 2;
  c.lens.vignetting.barrel_diameter_mm = 1.2 * aperture;
  c.lens.vignetting.barrel_distance_mm = 0.5 * focal;
  Image both = render_image(scene, 64);
  const int m = kSize / 2;
  // The centre's pixels see the whole aperture: the very same values.
  for (int y = m - 1; y <= m; ++y)
    for (int x = m - 1; x <= m; ++x) EXPECT_EQ(both.at(x, y, 1), natural.at(x, y, 1));
  // The corner: well below cos⁴.
  EXPECT_LT(both.at(kSize - 1, kSize - 1, 1), 0.5 * mean_cos4(kSize - 1, kSize - 1));
  EXPECT_LT(both.at(0, 0, 1), 0.5 * mean_cos4(0, 0));
  // The rasterizer's gain on a white film matches the tracer's image within its noise.
  Film white(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) white.add_sample({x, y}, Rgb(1));
  raster::apply_vignetting(white, c);
  for (int k : {0, 8, 16, 20, 23})
    EXPECT_NEAR(white.pixel({m + k, m + k}).g, both.at(m + k, m + k, 1), 0.03)
        << "diagonal pixel " << m + k;
}

}  // namespace
}  // namespace obscura

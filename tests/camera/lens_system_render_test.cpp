// The limit case: a single thin, slow element traced as a lens system renders the image of the
// thin-lens camera with the same focal length, f-number and focus (depth of field included), to
// within the noise of the two renders; the lens-system camera's rays are upright, weighted to
// the same exposure, and focused where asked.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "camera/thin_element.h"
#include "lens_optics.h"
#include "obscura/camera/focused_lens_system.h"
#include "obscura/scene/scene.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "white_on_black.h"

namespace obscura {
namespace {

constexpr int kWidth = 48, kHeight = 32;
constexpr double kFocusM = 2;  // from the thin lens

// Emitting squares: a checkerboard on the focus plane and one square in front of it, out of
// focus.
Scene squares() {
  Scene scene = test::white_on_black("squares");
  auto square = [&](double cx, double cy, double z, double half) {
    Mesh m;
    m.name = "square";
    const auto x0 = float(cx - half), x1 = float(cx + half), y0 = float(cy - half),
               y1 = float(cy + half);
    m.positions = {{x0, y0, float(z)}, {x1, y0, float(z)}, {x1, y1, float(z)}, {x0, y1, float(z)}};
    m.indices = {0, 1, 2, 0, 2, 3};
    scene.add_mesh(m);
  };
  for (int j = -3; j <= 3; ++j)
    for (int i = -4; i <= 4; ++i)
      if ((i + j) % 2 == 0) square(0.03 * i, 0.03 * j, -kFocusM, 0.015);
  square(-0.04, 0.01, -1.2, 0.02);
  return scene;
}

Image render_image(const Scene& scene, const Camera& camera, uint64_t seed) {
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film film(kWidth, kHeight);
  render(trace, camera, PathTracer(), {.samples_per_pixel = 64, .seed = seed}, film);
  return film.to_image();
}

double rmse(const Image& a, const Image& b) {
  double sum = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      double d = a.at(x, y, 1) - b.at(x, y, 1);
      sum += d * d;
    }
  return std::sqrt(sum / (kWidth * kHeight));
}

TEST(LensSystemRender, ThinElementConvergesToTheThinLensImage) {
  const LensPrescription element = test::thin_element();
  const test::ParaxialOptics optics = test::paraxial_optics(element);
  const double sensor_width_mm = 12;
  Scene scene = squares();
  // The thin lens: its centre at the origin, the sensor at the image distance behind it.
  Camera thin;
  Perspective perspective;
  perspective.focal_length_mm = optics.efl_mm;
  perspective.sensor_width_mm = sensor_width_mm;
  perspective.sensor_height_mm = sensor_width_mm * kHeight / kWidth;
  thin.projection = perspective;
  thin.film.width_px = kWidth;
  thin.film.height_px = kHeight;
  thin.near_m = 1e-3;
  thin.far_m = 100;
  thin.lens.depth_of_field = true;
  thin.lens.f_number = optics.f_number();
  thin.lens.focus_distance_m = kFocusM;
  thin.validate();
  // The lens system: its camera sits at its sensor, the element's middle at the origin, focused
  // on the same plane (2 m in front of the element: 2 m + the image distance from the sensor).
  auto lens = std::make_shared<const LensSystem>(element);
  Camera real = thin;
  LensSystemProjection projection;
  projection.lens = lens;
  projection.sensor_width_mm = sensor_width_mm;
  real.projection = projection;
  real.lens.depth_of_field = false;
  const double image_distance_mm =
      optics.efl_mm * kFocusM * 1000 / (kFocusM * 1000 - optics.efl_mm);
  real.lens.focus_distance_m = kFocusM + image_distance_mm / 1000;
  const double film_mm = focused_lens_system(lens, real.lens_system_settings())->film_distance_mm();
  real.world_from_camera = AnimatedTransform(Transform::translate({0, 0, (film_mm + 0.5) / 1000}));
  real.validate();

  Image thin_a = render_image(scene, thin, 1), thin_b = render_image(scene, thin, 2);
  // Focused at 2 m the sensor sits at v = f·S/(S − f) rather than f, and the cone of light
  // reaching it narrows by f / v: the real lens's irradiance is (f / v)² of the thin-lens
  // camera's, whose exposure stays at f/N whatever the focus (thin_lens.h). The bellows factor,
  // 0.90 here, applied to the thin lens's images.
  const double bellows = std::pow(optics.efl_mm / image_distance_mm, 2);
  for (Image* image : {&thin_a, &thin_b})
    for (float& v : image->data) v *= float(bellows);
  Image real_a = render_image(scene, real, 1), real_b = render_image(scene, real, 2);
  // Two independent renders of each camera differ by their noise alone; the two cameras' images
  // must differ by no more than that noise (the expected difference of independent estimates of
  // the same image, √(σ_thin² + σ_real²), each σ² half the squared RMSE of its two renders).
  const double noise =
      std::sqrt(0.5 * std::pow(rmse(thin_a, thin_b), 2) + 0.5 * std::pow(rmse(real_a, real_b), 2));
  EXPECT_LT(rmse(thin_a, real_a), 1.25 * noise)
      << "thin vs lens system " << rmse(thin_a, real_a) << ", noise " << noise;
  // And the images carry something: the checkerboard's squares are lit.
  double total = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) total += real_a.at(x, y, 1);
  EXPECT_GT(total / (kWidth * kHeight), 0.2);
}

// A lens whose glass disperses tells the renderer so, and bends each wavelength its own way: the
// camera ray for the same film and lens point leaves in a different direction for blue (F line)
// and red (C line) light (a ray off the lens centre is bent by the element's power, and
// n_F > n_C), while the default wavelength is the d line. The spectral tracer then gives each
// camera ray its path's hero wavelength and renders a lit image.
TEST(LensSystemRender, ADispersiveLensBendsEachWavelengthItsOwnWay) {
  LensPrescription element = test::thin_element();
  auto camera_with = [&](double abbe_number) {
    LensPrescription p = element;
    p.surfaces[1].abbe_number = abbe_number;
    Camera camera;
    LensSystemProjection projection;
    projection.lens = std::make_shared<const LensSystem>(p);
    projection.sensor_width_mm = 12;
    camera.projection = projection;
    camera.film.width_px = kWidth;
    camera.film.height_px = kHeight;
    camera.near_m = 1e-3;
    camera.lens.focus_distance_m = 2.1;
    camera.validate();
    return camera;
  };
  const Camera plain = camera_with(0), dispersive = camera_with(20);
  EXPECT_FALSE(plain.prepare().disperses());
  const PreparedCamera prepared = dispersive.prepare();
  ASSERT_TRUE(prepared.disperses());
  const Point2d corner(2, 2), off_centre(0.7, 0.5);
  auto blue = prepared.generate_ray(corner, off_centre, 0, 486.1327);
  auto red = prepared.generate_ray(corner, off_centre, 0, 656.2725);
  auto d_line = prepared.generate_ray(corner, off_centre, 0, kWavelengthD_nm);
  auto by_default = prepared.generate_ray(corner, off_centre);
  ASSERT_TRUE(blue && red && d_line && by_default);
  EXPECT_EQ(by_default->direction.x, d_line->direction.x);
  EXPECT_EQ(by_default->direction.y, d_line->direction.y);
  EXPECT_GT(length(blue->direction - red->direction), 1e-4);

  TraceScene trace(squares(), std::make_shared<EmbreeDevice>());
  Film film(kWidth, kHeight);
  render(trace, dispersive, PathTracer(), {.samples_per_pixel = 8, .seed = 1, .spectral = true},
         film);
  double total = 0;
  for (float v : film.to_image().data) total += v;
  EXPECT_GT(total, 0);
}

}  // namespace
}  // namespace obscura

// Ghost flares against optics computed here: a ghost's energy relative to the direct image is
// the product of the Fresnel reflectances and transmittances of its path, a coating scales it by
// the thin-film reflectances (the Airy intensity formula with the CIE observer), ghosts of an
// off-axis light line up on the line through the image centre, the image is the same for any
// thread count, and the scene's lights become sources of the right intensity.
#include "obscura/render/lens_flare.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

#include "obscura/camera/builtin_lenses.h"
#include "obscura/camera/lens_system_projection.h"
#include "obscura/color/cie_tables.h"
#include "obscura/color/spectral_working_space.h"
#include "obscura/math/error.h"
#include "obscura/scene/shapes.h"

namespace obscura {
namespace {

double squared(double x) {
  return x * x;
}

double channel_sum(const Image& image, int c) {
  double sum = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum;
}

Point2d centroid(const Image& image) {
  double sx = 0, sy = 0, s = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double v = image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2);
      sx += v * (x + 0.5), sy += v * (y + 0.5), s += v;
    }
  return {sx / s, sy / s};
}

// A biconvex singlet of non-dispersive glass behind a small stop in front of it: only the stop
// limits the light, so a ghost reflected behind it keeps every ray the direct image has.
constexpr double kGlass = 1.6;
LensPrescription stopped_singlet() {
  LensPrescription p;
  p.name = "singlet";
  p.surfaces = {
      {.radius_mm = 0, .thickness_mm = 2, .n_d = 1, .aperture_diameter_mm = 2, .is_stop = true},
      {.radius_mm = 80, .thickness_mm = 6, .n_d = kGlass, .aperture_diameter_mm = 60},
      {.radius_mm = -80, .n_d = 1, .aperture_diameter_mm = 60},
  };
  return p;
}

Camera lens_camera(std::shared_ptr<const LensSystem> lens, int width, int height,
                   LensCoating coating, double sensor_width_mm = 36) {
  Camera camera;
  LensSystemProjection projection;
  projection.lens = std::move(lens);
  projection.sensor_width_mm = sensor_width_mm;
  projection.coating = coating;
  camera.projection = projection;
  camera.film.width_px = width;
  camera.film.height_px = height;
  camera.lens.focus_distance_m = std::numeric_limits<double>::infinity();
  camera.validate();
  return camera;
}

FlareSource on_axis_star() {
  FlareSource s;
  s.at_infinity = true;
  s.direction = {0, 0, 1};  // travelling into the camera, which looks down −Z
  s.intensity = Rgb(1.f);
  return s;
}

// Ghost (2, 1) of the singlet passes surface 1, reflects at 2, reflects at 1, passes 2; the
// direct image passes both: their ratio is R₁·R₂ at (near-)normal incidence.
TEST(LensFlare, GhostEnergyOverTheDirectImageIsTheProductOfReflectances) {
  const auto lens = std::make_shared<const LensSystem>(stopped_singlet());
  const Camera camera = lens_camera(lens, 200, 200, LensCoating{});
  const FlareSource star = on_axis_star();
  const Image direct = lens_path_image(star, camera, direct_path(*lens));
  const Image ghost = lens_path_image(star, camera, ghost_path(*lens, {2, 1}));
  const double r = squared((kGlass - 1) / (kGlass + 1));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(channel_sum(ghost, c) / channel_sum(direct, c), r * r, 0.01 * r * r) << c;
}

// The same in the double-Gauss (its glasses made non-dispersive, so that R is the same at every
// wavelength) stopped down to f/16: for ghosts between surfaces behind the stop, which see
// the bundle the stop lets in, the ratio also carries (1 − R)² of each surface between the two
// reflections, met twice more.
TEST(LensFlare, DoubleGaussGhostsBehindTheStopCarryTheirFresnelProduct) {
  LensPrescription p = builtin_lens("double-gauss-50mm")->prescription();
  for (LensSurface& s : p.surfaces) s.abbe_number = 0;
  const auto lens = std::make_shared<const LensSystem>(p);
  Camera camera = lens_camera(lens, 240, 240, LensCoating{}, 24);
  std::get<LensSystemProjection>(camera.projection).f_number = 16;
  const FlareSource star = on_axis_star();
  const Image direct = lens_path_image(star, camera, direct_path(*lens));
  const double direct_power = channel_sum(direct, 1);
  auto bare_r = [&](int i) {
    const double n1 = i == 0 ? 1 : p.surfaces[size_t(i) - 1].n_d, n2 = p.surfaces[size_t(i)].n_d;
    return squared((n2 - n1) / (n2 + n1));
  };
  const int stop = stop_index(p);
  int checked = 0;
  for (const Ghost& g : lens_ghosts(*lens)) {
    if (g.second < stop) continue;
    double expected = bare_r(g.first) * bare_r(g.second);
    for (int k = g.second + 1; k < g.first; ++k) expected *= squared(1 - bare_r(k));
    const Image ghost = lens_path_image(star, camera, ghost_path(*lens, g));
    EXPECT_NEAR(channel_sum(ghost, 1) / direct_power, expected, 0.02 * expected)
        << g.first << "," << g.second;
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

// A quarter-wave coating scales the singlet's ghost by the ratio of the coated to the bare
// reflectances, integrated here over 400–700 nm with the CIE 1931 observer in linear Rec.709
// (each channel's positive response), the coating's reflectance from the Airy intensity formula
// at normal incidence.
TEST(LensFlare, ACoatingScalesAGhostByItsReflectances) {
  const auto lens = std::make_shared<const LensSystem>(stopped_singlet());
  const LensCoating coating = quarter_wave_coating(1.38, 550);
  const FlareSource star = on_axis_star();
  const Image bare =
      lens_path_image(star, lens_camera(lens, 200, 200, LensCoating{}), ghost_path(*lens, {2, 1}));
  const Image coated =
      lens_path_image(star, lens_camera(lens, 200, 200, coating), ghost_path(*lens, {2, 1}));
  auto coated_r = [&](double nm) {
    const double ra = (1 - 1.38) / (1 + 1.38), rb = (1.38 - kGlass) / (1.38 + kGlass);
    const double cos_2delta = std::cos(4 * std::numbers::pi * 1.38 * coating.thickness_nm / nm);
    return (ra * ra + rb * rb + 2 * ra * rb * cos_2delta) /
           (1 + ra * ra * rb * rb + 2 * ra * rb * cos_2delta);
  };
  const double bare_r = squared((kGlass - 1) / (kGlass + 1));
  double expected[3] = {}, weights[3] = {};
  const SpectralTable& cmf = cie1931_cmf();
  for (int nm = 400; nm < 700; ++nm) {
    const int row = nm - cmf.first_nm;
    const Vec3d rgb =
        working_rgb_from_xyz() * Vec3d{cmf.at(row, 0), cmf.at(row, 1), cmf.at(row, 2)};
    const double rc = coated_r(nm + 0.5);
    const double ratio = squared(rc) * squared(1 - rc) / (squared(bare_r) * squared(1 - bare_r));
    for (int c = 0; c < 3; ++c) {
      const double w = std::max(0.0, rgb[size_t(c)]);
      expected[c] += w * ratio, weights[c] += w;
    }
  }
  for (int c = 0; c < 3; ++c) {
    const double want = expected[c] / weights[c];
    EXPECT_NEAR(channel_sum(coated, c) / channel_sum(bare, c), want, 0.03 * want) << c;
  }
  // Coated ghosts are purple: the coating reflects least in the green.
  EXPECT_LT(channel_sum(coated, 1), channel_sum(coated, 0));
  EXPECT_LT(channel_sum(coated, 1), channel_sum(coated, 2));
}

// In a rotationally symmetric lens every ghost of a point lies on the line through the image
// centre and the point's image. On a square sensor, along its diagonal, the frame's edges cut
// the ghosts symmetrically about that line too.
TEST(LensFlare, GhostsOfAnOffAxisLightLieOnTheLineThroughTheCentre) {
  const auto lens = builtin_lens("double-gauss-50mm");
  const Camera camera = lens_camera(lens, 160, 160, quarter_wave_coating(), 24);
  FlareSource star = on_axis_star();
  star.direction = Vector3d(-0.12, -0.12, 1) / length(Vector3d(-0.12, -0.12, 1));
  const Point2d image = centroid(lens_path_image(star, camera, direct_path(*lens)));
  const Point2d centre(80, 80);
  const Vector2d axis = Vector2d(image.x - centre.x, image.y - centre.y) /
                        std::hypot(image.x - centre.x, image.y - centre.y);
  int checked = 0;
  for (const Ghost& g : lens_ghosts(*lens)) {
    const Image ghost = lens_path_image(star, camera, ghost_path(*lens, g));
    if (!(channel_sum(ghost, 1) > 0)) continue;
    const Point2d c = centroid(ghost);
    const double off_line = std::abs((c.x - centre.x) * axis.y - (c.y - centre.y) * axis.x);
    EXPECT_LT(off_line, 1.0) << g.first << "," << g.second;
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

Scene street_lights() {
  Scene scene;
  scene.lights.push_back({"lamp", PointLight{{0.5f, 0.3f, -8}, Rgb(200.f, 150.f, 80.f)}});
  scene.lights.push_back({"sun", DirectionalLight{Vector3f(0.05f, -0.08f, 1), Rgb(0.5f)}});
  return scene;
}

TEST(LensFlare, TheImageIsTheSameForAnyThreadCount) {
  const Camera camera = lens_camera(builtin_lens("double-gauss-50mm"), 96, 64, LensCoating{});
  const Scene scene = street_lights();
  FlareSettings settings;
  settings.grid_cells = 24;
  Image one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = lens_flare_image(scene, camera, settings);
  }
  const Image many = lens_flare_image(scene, camera, settings);
  ASSERT_EQ(one.data.size(), many.data.size());
  EXPECT_EQ(one.data, many.data);
  double total = 0;
  for (float v : many.data) total += v;
  EXPECT_GT(total, 0);
}

TEST(LensFlare, SourcesCarryTheirIntensityTowardsTheCamera) {
  Scene scene = street_lights();
  // A spot turned away from the camera sends it nothing.
  scene.lights.push_back({"away", SpotLight{.position = {0, 0, -5}, .direction = {0, 0, -1}}});
  // An emissive sphere of radius r and radiance L: intensity L·π·r² towards any direction.
  Material glow = diffuse_material("glow", Rgb(0.f), Rgb(100.f, 50.f, 10.f));
  scene.materials.push_back(glow);
  Mesh sphere = make_sphere(0.2f, 96);
  sphere.material = 0;
  scene.add_mesh(sphere, Transform::translate({1, 0, -10}));
  Camera camera;
  const std::vector<FlareSource> sources = flare_sources(scene, camera);
  ASSERT_EQ(sources.size(), 3u);
  EXPECT_EQ(sources[0].name, "lamp");
  EXPECT_TRUE(sources[1].at_infinity);
  const double area = std::numbers::pi * 0.2 * 0.2;
  EXPECT_NEAR(sources[2].intensity.r, 100 * area, 0.01 * 100 * area);
  EXPECT_NEAR(sources[2].intensity.b, 10 * area, 0.01 * 10 * area);
  EXPECT_NEAR(sources[2].position.x, 1, 0.02);
  EXPECT_NEAR(sources[2].position.z, -10, 0.2);  // the centroid of the visible hemisphere
}

TEST(LensFlare, NeedsALensSystemCamera) {
  EXPECT_THROW(lens_flare_image(street_lights(), Camera{}), Error);
  FlareSettings bad;
  bad.grid_cells = 1;
  EXPECT_THROW(validate(bad), Error);
}

}  // namespace
}  // namespace obscura

// A lens system in a camera: focused at S it images a point at S to a spot smaller than a pixel;
// its rays expose the image centre as the thin lens at the same f-number does (π / 4N²); its
// relative illumination falls towards the corners, where the pupil turns into a cat's eye; the
// image is upright on the film, and project / unproject invert each other along chief rays.
#include "obscura/camera/focused_lens_system.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "obscura/camera/builtin_lenses.h"
#include "obscura/camera/camera.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kDegrees = std::numbers::pi / 180;

LensSettings focus_at(double focus_distance_m, double f_number = 0) {
  LensSettings s;
  s.focus_distance_m = focus_distance_m;
  s.f_number = f_number;
  return s;
}

// The RMS distance from their centroid of the points where rays from `object` (lens space)
// through a grid over the front element land on the focused lens's sensor plane.
double rms_spot_radius_mm(const FocusedLensSystem& focused, Point3d object, int* rays = nullptr) {
  const LensSystem& lens = focused.lens();
  const double sensor_z = -focused.film_distance_mm();
  TraceOptions options;
  options.stop = focused.stop();
  // Two passes: a coarse grid over the front element finds the part that passes (a small
  // entrance pupil may cover a few cells), then a fine grid over that part.
  double x0 = -0.5 * lens.prescription().surfaces.front().aperture_diameter_mm, x1 = -x0;
  double y0 = x0, y1 = x1;
  std::vector<Point2d> hits;
  constexpr int kGrid = 64;
  for (int pass = 0; pass < 2; ++pass) {
    hits.clear();
    double nx0 = 1e9, nx1 = -1e9, ny0 = 1e9, ny1 = -1e9;
    const double cx = (x1 - x0) / kGrid, cy = (y1 - y0) / kGrid;
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        Point3d target(x0 + (i + 0.5) * cx, y0 + (j + 0.5) * cy, lens.front_z_mm());
        Vector3d d = target - object;
        auto out = lens.trace({object, d / length(d)}, TraceFrom::scene, options);
        if (!out) continue;
        nx0 = std::min(nx0, target.x), nx1 = std::max(nx1, target.x);
        ny0 = std::min(ny0, target.y), ny1 = std::max(ny1, target.y);
        double t = (sensor_z - out->origin.z) / out->direction.z;
        hits.push_back(
            {out->origin.x + t * out->direction.x, out->origin.y + t * out->direction.y});
      }
    x0 = nx0 - cx, x1 = nx1 + cx, y0 = ny0 - cy, y1 = ny1 + cy;
  }
  if (rays) *rays = int(hits.size());
  Point2d c(0, 0);
  for (Point2d h : hits) c = {c.x + h.x / hits.size(), c.y + h.y / hits.size()};
  double sum = 0;
  for (Point2d h : hits) sum += (h.x - c.x) * (h.x - c.x) + (h.y - c.y) * (h.y - c.y);
  return std::sqrt(sum / hits.size());
}

TEST(FocusedLensSystem, PointAtTheFocusDistanceImagesSmallerThanAPixel) {
  // A 36 mm sensor 640 pixels wide: 56 µm pixels.
  const double pixel_mm = 36.0 / 640;
  for (const char* name : {"double-gauss-50mm", "telephoto-250mm", "fisheye-10mm"}) {
    const double focus_m = 3;
    FocusedLensSystem focused(builtin_lens(name), focus_at(focus_m));
    // The object at 3 m from the sensor, on the axis: lens space z = S − d.
    const double object_z = focus_m * 1000 - focused.film_distance_mm();
    int rays = 0;
    double on_axis = rms_spot_radius_mm(focused, {0, 0, object_z}, &rays);
    EXPECT_GT(rays, 1000) << name;
    EXPECT_LT(on_axis, pixel_mm) << name << ": RMS spot " << on_axis * 1000 << " µm";
  }
  // The double-Gauss at a moderate field: 10° off the axis, stopped to f/4 (wide open its
  // off-axis coma and astigmatism spread a 10° point over ~2 pixels, as the real lens does).
  FocusedLensSystem focused(builtin_lens("double-gauss-50mm"), focus_at(3, 4));
  const double object_z = 3000 - focused.film_distance_mm();
  const double off_axis = rms_spot_radius_mm(
      focused, {0, std::tan(10 * kDegrees) * (object_z - focused.lens().front_z_mm()), object_z});
  EXPECT_LT(off_axis, pixel_mm) << "RMS spot " << off_axis * 1000 << " µm";
}

TEST(FocusedLensSystem, FocusingAtInfinityPutsTheSensorNearTheBackFocalDistance) {
  auto lens = builtin_lens("double-gauss-50mm");
  FocusedLensSystem at_infinity(lens, focus_at(kInfinity));
  // The sharpest focus wide open lies a little inside the paraxial one (spherical aberration).
  EXPECT_NEAR(at_infinity.film_distance_mm(), lens->back_focal_distance_mm(), 0.2);
  // Closer focus moves the lens out by about f² / (S − f) (Newton's x·x' = f²).
  FocusedLensSystem at_1m(lens, focus_at(1));
  const double f = lens->effective_focal_length_mm();
  const double extension = at_1m.film_distance_mm() - lens->back_focal_distance_mm();
  EXPECT_NEAR(extension, f * f / (1000 - 2 * f), 0.15 * extension);
  EXPECT_THROW(FocusedLensSystem(lens, focus_at(0.05)), Error);
  EXPECT_THROW(FocusedLensSystem(lens, focus_at(10, 1.4)), Error);  // opens to f/2 at most
}

// The mean ray weight at image point p over a grid of lens samples: the irradiance there
// relative to the thin lens at the same f-number (0 for blocked rays).
double relative_illumination(const FocusedLensSystem& focused, Point2d p) {
  constexpr int kGrid = 48;
  double sum = 0;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i)
      if (auto r = focused.ray(p, {(i + 0.5) / kGrid, (j + 0.5) / kGrid})) sum += r->weight;
  return sum / (kGrid * kGrid);
}

TEST(FocusedLensSystem, ImageCentreIsExposedAsTheThinLensAtTheSameFNumber) {
  // A slow singlet with the stop at the lens, focused at infinity: its image-side cone from the
  // axial point has sin u' = 1 / (2N) to well under 1 %, so its irradiance is the thin lens's
  // π L / (4 N²) and the weights must average 1.
  LensPrescription p;
  p.name = "slow singlet";
  p.surfaces = {
      {.radius_mm = 0,
       .thickness_mm = 0.5,
       .n_d = 1,
       .aperture_diameter_mm = 12.5,
       .is_stop = true},
      {.radius_mm = 100, .thickness_mm = 1, .n_d = 1.5, .aperture_diameter_mm = 20},
      {.radius_mm = -100, .n_d = 1, .aperture_diameter_mm = 20},
  };
  auto lens = std::make_shared<const LensSystem>(p);
  FocusedLensSystem focused(lens, focus_at(kInfinity));
  EXPECT_NEAR(focused.f_number(), 100.0 / 12.5, 0.1);
  EXPECT_NEAR(relative_illumination(focused, {0, 0}), 1, 0.01);
  // Stopped down to f/16 the exposure's f-number follows, and the centre stays at 1.
  FocusedLensSystem stopped(lens, focus_at(kInfinity, 16));
  EXPECT_NEAR(stopped.stop().radius_mm, 12.5 / 2 * focused.f_number() / 16, 1e-9);
  EXPECT_NEAR(relative_illumination(stopped, {0, 0}), 1, 0.01);
}

TEST(FocusedLensSystem, IlluminationFallsTowardsTheCornersWithACatsEyePupil) {
  const LensSettings settings = focus_at(kInfinity);
  FocusedLensSystem focused(builtin_lens("double-gauss-50mm"), settings);
  const Point2d corner(18, 12);
  double centre = relative_illumination(focused, {0, 0});
  double half = relative_illumination(focused, {corner.x / 2, corner.y / 2});
  double edge = relative_illumination(focused, {corner.x * 0.95, corner.y * 0.95});
  EXPECT_NEAR(centre, 1, 0.05);  // an f/2 double-Gauss nearly obeys the sine condition
  EXPECT_LT(half, centre);
  EXPECT_LT(edge, 0.7 * half);
  // The set of pupil points that pass, on a fine grid of the rear vertex plane: a circle on the
  // axis; off axis the lens's front and rear rims cut it from both sides into a cat's eye,
  // narrower along the radius (x here) than across it.
  auto passing = [&](double film_radius) {
    struct Extent {
      double area = 0, width = 0, height = 0;
    } e;
    const double reach = 15;
    constexpr int kGrid = 200;
    const double cell = 2 * reach / kGrid;
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        Point2d q(-reach + (i + 0.5) * cell, -reach + (j + 0.5) * cell);
        if (!focused.passes(film_radius, q)) continue;
        e.area += cell * cell;
        x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y),
        y1 = std::max(y1, q.y);
      }
    e.width = x1 - x0 + cell, e.height = y1 - y0 + cell;
    return e;
  };
  auto on_axis = passing(0);
  auto off_axis = passing(0.95 * std::hypot(corner.x, corner.y));
  EXPECT_NEAR(on_axis.width / on_axis.height, 1, 0.03);
  EXPECT_NEAR(on_axis.area, std::numbers::pi / 4 * on_axis.width * on_axis.height,
              0.03 * on_axis.area);  // a disk fills π/4 of its square
  EXPECT_LT(off_axis.area, 0.7 * on_axis.area);
  EXPECT_LT(off_axis.width / off_axis.height, 0.85);
  // The exit-pupil bounds hold every passing point.
  PupilBounds b = focused.pupil_bounds(0.95 * std::hypot(corner.x, corner.y));
  EXPECT_LE(b.x_max - b.x_min, off_axis.width + 3);
  EXPECT_GE(b.x_max - b.x_min, off_axis.width - 1e-9);
}

Camera lens_camera(const std::string& lens, int width = 96, int height = 64) {
  Camera c;
  LensSystemProjection projection;
  projection.lens = builtin_lens(lens);
  c.projection = projection;
  c.film.width_px = width;
  c.film.height_px = height;
  c.lens.focus_distance_m = 3;
  c.near_m = 1e-3;
  c.far_m = 1e6;
  c.validate();
  return c;
}

TEST(LensSystemCamera, ImageIsUprightAndProjectInvertsUnproject) {
  Camera c = lens_camera("double-gauss-50mm");
  // A film point near the top of the image sees upwards, one at the left sees left: the lens
  // inverts the image on the sensor and the film point is flipped back.
  auto top = c.generate_ray({48, 4}, {0.5, 0.5});
  auto left = c.generate_ray({4, 32}, {0.5, 0.5});
  ASSERT_TRUE(top && left);
  EXPECT_GT(top->direction.y, 0.1);
  EXPECT_LT(left->direction.x, -0.1);
  EXPECT_LT(top->origin.z, -0.03);  // rays leave the front of the lens, in front of the sensor
  EXPECT_GT(top->weight, 0);
  for (Point2d p : {Point2d(48, 32), Point2d(10, 7), Point2d(90, 60), Point2d(30, 50)}) {
    auto world = c.unproject(p, 4);
    ASSERT_TRUE(world);
    auto back = c.project(*world);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->film_point.x, p.x, 1e-6);
    EXPECT_NEAR(back->film_point.y, p.y, 1e-6);
    EXPECT_NEAR(back->depth_m, 4, 1e-9);
  }
  // The f-number the exposure uses is the lens's, or the stopped-down one.
  EXPECT_NEAR(c.f_number(), builtin_lens("double-gauss-50mm")->f_number(), 1e-12);
  std::get<LensSystemProjection>(c.projection).f_number = 8;
  EXPECT_EQ(c.f_number(), 8);
  std::get<LensSystemProjection>(c.projection).f_number = 1.2;
  EXPECT_THROW(c.validate(), Error);
}

TEST(LensSystemCamera, FieldOfViewFollowsTheFocalLength) {
  // The double-Gauss on a 36 mm sensor sees about 2·atan(18 / f) horizontally (within its 1 %
  // or so of distortion).
  Camera c = lens_camera("double-gauss-50mm", 90, 60);
  c.lens.focus_distance_m = kInfinity;
  double f = builtin_lens("double-gauss-50mm")->effective_focal_length_mm();
  EXPECT_NEAR(c.fov_degrees().x, 2 * std::atan(18 / f) / kDegrees, 0.01 * 40);
  EXPECT_NEAR(c.fov_degrees().y, 2 * std::atan(12 / f) / kDegrees, 0.01 * 27);
}

}  // namespace
}  // namespace obscura

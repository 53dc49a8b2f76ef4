// The lens system against optics computed independently: the built-in designs' focal length,
// back focal distance and f-number against the test's paraxial ABCD matrices, the fisheye's
// field of view, a perfect aspheric singlet, and a dispersive singlet's lateral and longitudinal
// colour against the paraxial prediction from catalogue indices.
#include "obscura/camera/lens_system.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "lens_optics.h"
#include "obscura/camera/builtin_lenses.h"
#include "obscura/camera/focused_lens_system.h"

namespace obscura {
namespace {

constexpr double kDegrees = std::numbers::pi / 180;

// Where a ray (lens space) crosses the axis in its meridional plane (y–z).
double axis_crossing_z(const LensRay& r) {
  return r.origin.z - r.origin.y / r.direction.y * r.direction.z;
}

// The height where the ray meets the plane z.
double height_at(const LensRay& r, double z) {
  return r.origin.y + (z - r.origin.z) / r.direction.z * r.direction.y;
}

// A ray parallel to the axis at height h from in front of the lens.
std::optional<LensRay> parallel_ray(const LensSystem& lens, double h, TraceOptions options = {}) {
  return lens.trace({{0, h, lens.front_z_mm() + 10}, {0, 0, -1}}, TraceFrom::scene, options);
}

class BuiltinLens : public testing::TestWithParam<const char*> {};

TEST_P(BuiltinLens, FocalLengthBackFocusAndFNumberMatchParaxialRayTransfer) {
  auto lens = builtin_lens(GetParam());
  test::ParaxialOptics expected = test::paraxial_optics(lens->prescription());
  // Measured by tracing a real parallel ray at 2 % of the entrance pupil's radius (its angle
  // gives the EFL, its axis crossing the BFD) …
  const double h = 0.02 * expected.entrance_pupil_mm / 2;
  TraceOptions no_apertures;
  no_apertures.apertures = false;
  auto out = parallel_ray(*lens, h, no_apertures);
  ASSERT_TRUE(out);
  double efl = -h / (out->direction.y / -out->direction.z);
  double bfd = -axis_crossing_z(*out);
  EXPECT_NEAR(efl, expected.efl_mm, 0.005 * expected.efl_mm) << GetParam();
  EXPECT_NEAR(bfd, expected.bfd_mm, 0.005 * expected.bfd_mm) << GetParam();
  // … and the f-number from the stop: a near-axial ray's height at the stop against its height
  // in front of the lens scales the stop's diameter to the entrance pupil's.
  Point3d at_stop;
  no_apertures.at_stop = &at_stop;
  ASSERT_TRUE(parallel_ray(*lens, h, no_apertures));
  const LensSurface& stop = lens->prescription().surfaces[size_t(stop_index(lens->prescription()))];
  double entrance_pupil = stop.aperture_diameter_mm * h / std::abs(at_stop.y);
  EXPECT_NEAR(efl / entrance_pupil, expected.f_number(), 0.005 * expected.f_number()) << GetParam();
  // The lens system's own first-order numbers.
  EXPECT_NEAR(lens->effective_focal_length_mm(), expected.efl_mm, 0.005 * expected.efl_mm);
  EXPECT_NEAR(lens->back_focal_distance_mm(), expected.bfd_mm, 0.005 * expected.bfd_mm);
  EXPECT_NEAR(lens->f_number(), expected.f_number(), 0.005 * expected.f_number());
}

INSTANTIATE_TEST_SUITE_P(Designs, BuiltinLens,
                         testing::Values("double-gauss-50mm", "telephoto-250mm", "fisheye-10mm"));

TEST(LensSystem, PublishedFocalLengthsAndFNumbers) {
  // The designs' nominal values (data/lenses/README.md): 50 mm f/2, 250 mm, 10 mm f/4.
  EXPECT_NEAR(builtin_lens("double-gauss-50mm")->effective_focal_length_mm(), 50, 0.5);
  EXPECT_NEAR(builtin_lens("double-gauss-50mm")->f_number(), 2, 0.05);
  EXPECT_NEAR(builtin_lens("telephoto-250mm")->effective_focal_length_mm(), 250, 2.5);
  EXPECT_NEAR(builtin_lens("fisheye-10mm")->effective_focal_length_mm(), 10, 0.1);
  EXPECT_NEAR(builtin_lens("fisheye-10mm")->f_number(), 4, 0.1);
}

// The chief ray (through the stop's centre) at field angle θ from the scene, found by aiming:
// the height at the front vertex plane whose ray crosses the stop on the axis (a scan across the
// front element for the sign change, then bisection).
std::optional<LensRay> chief_ray_from_scene(const LensSystem& lens, double theta, bool apertures) {
  Point3d at_stop;
  TraceOptions options;
  options.at_stop = &at_stop;
  options.apertures = false;
  Vector3d d(0, -std::sin(theta), -std::cos(theta));
  auto stop_height = [&](double h) -> std::optional<double> {
    Point3d o(0, h, lens.front_z_mm());
    if (!lens.trace({o - d * 20.0, d}, TraceFrom::scene, options)) return std::nullopt;
    return at_stop.y;
  };
  // Steep rays cross the front vertex plane far above where they meet the curved front surface.
  const double reach = 2 * lens.prescription().surfaces.front().aperture_diameter_mm;
  constexpr int kScan = 2000;
  std::optional<double> low, high;
  std::optional<double> previous;
  for (int i = 0; i <= kScan && !high; ++i) {
    double h = -reach + 2 * reach * i / kScan;
    std::optional<double> y = stop_height(h);
    if (y && previous && (*y > 0) != (*stop_height(h - 2 * reach / kScan) > 0)) {
      low = h - 2 * reach / kScan;
      high = h;
    }
    previous = y;
  }
  if (!low) return std::nullopt;
  double a = *low, b = *high;
  bool a_positive = *stop_height(a) > 0;
  for (int i = 0; i < 60; ++i) {
    double mid = 0.5 * (a + b);
    std::optional<double> y = stop_height(mid);
    if (!y) return std::nullopt;
    ((*y > 0) == a_positive ? a : b) = mid;
  }
  options.apertures = apertures;
  Point3d o(0, a, lens.front_z_mm());
  return lens.trace({o - d * 20.0, d}, TraceFrom::scene, options);
}

TEST(LensSystem, FisheyeSeesItsPublishedFieldAcrossTheFormatItWasDesignedFor) {
  // Muller's design is a 16 mm fisheye for the 35 mm format (36 × 24 mm, diagonal 43.27 mm).
  // The data are that design scaled by 10/16 (data/lenses/README.md), so its image fills the
  // format scaled by the same factor: a corner at 43.27/2 · 10/16 = 13.52 mm. (Scaling by the
  // traced EFL instead, 9.991 mm, moves the corner by 0.09 % and the field by 0.14°.) The field
  // across that diagonal, from the chief rays at its corners (through the stop's centre, found
  // here by aiming from the scene), against the published 155.9°. The tabulated clear apertures
  // vignette the chief ray from 149.5° on and all light from 153.8° on, so a real image circle
  // is a little smaller than the design's field.
  auto lens = builtin_lens("fisheye-10mm");
  const double corner_mm = 0.5 * std::hypot(36.0, 24.0) * 10.0 / 16.0;
  LensSettings settings;
  settings.focus_distance_m = std::numeric_limits<double>::infinity();
  settings.sensor_width_mm = 2 * corner_mm * 36 / std::hypot(36.0, 24.0);
  settings.sensor_height_mm = 2 * corner_mm * 24 / std::hypot(36.0, 24.0);
  FocusedLensSystem focused(lens, settings);
  // The field angle whose chief ray lands at the corner (the image height grows with the angle).
  double low = 0, high = 85 * kDegrees;
  for (int i = 0; i < 50; ++i) {
    double mid = 0.5 * (low + high);
    auto chief = chief_ray_from_scene(*lens, mid, false);
    ASSERT_TRUE(chief) << mid / kDegrees;
    (std::abs(height_at(*chief, -focused.film_distance_mm())) < corner_mm ? low : high) = mid;
  }
  const double field_degrees = 2 * low / kDegrees;
  EXPECT_NEAR(field_degrees, 155.9, 0.5);
  // The camera's chief rays (from the film, through FocusedLensSystem) see the same field.
  Point2d corner(corner_mm * 36 / std::hypot(36.0, 24.0), corner_mm * 24 / std::hypot(36.0, 24.0));
  auto a = focused.chief_ray(corner), b = focused.chief_ray({-corner.x, -corner.y});
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(std::acos(dot(a->direction, b->direction)) / kDegrees, field_degrees, 0.05);
}

// A plano-convex singlet, flat side to the scene, whose rear surface is the hyperboloid of
// conic constant −n²: the Cartesian surface that focuses a parallel beam inside glass of index n
// to one point in air, at R / (n − 1) behind the vertex. Every zone must cross the axis there,
// where a sphere's zones spread by its spherical aberration.
TEST(LensSystem, HyperbolicSingletFocusesEveryZoneToOnePoint) {
  const double n = 1.5, radius = 50;
  LensPrescription p;
  p.name = "hyperbolic";
  p.surfaces = {
      {.radius_mm = 0, .thickness_mm = 0, .n_d = 1, .aperture_diameter_mm = 40, .is_stop = true},
      {.radius_mm = 0, .thickness_mm = 8, .n_d = n, .aperture_diameter_mm = 40},
      {.radius_mm = -radius, .n_d = 1, .aperture_diameter_mm = 40, .conic = -n * n},
  };
  LensSystem lens(p);
  for (double h : {0.5, 5.0, 10.0, 15.0, 19.0}) {
    auto out = parallel_ray(lens, h);
    ASSERT_TRUE(out) << h;
    EXPECT_NEAR(-axis_crossing_z(*out), radius / (n - 1), 1e-9) << "zone " << h;
  }
  // The spherical surface of the same vertex radius focuses its rim zone well short of that.
  p.surfaces[2].conic = 0;
  LensSystem sphere(p);
  EXPECT_LT(-axis_crossing_z(*parallel_ray(sphere, 19.0)), radius / (n - 1) - 1);
}

TEST(LensSystem, PolynomialAsphereRayMeetsItsSag) {
  // A flat base with A4 and A6 terms: where the traced ray crosses the surface, the surface's
  // equation z = −(A4 r⁴ + A6 r⁶) (sag towards the sensor) must hold. Seen from after the
  // refraction: the ray's origin is the intersection point.
  const double a4 = 2e-5, a6 = -1e-8;
  LensPrescription p;
  p.name = "polynomial";
  p.surfaces = {
      {.radius_mm = 0, .thickness_mm = 1, .n_d = 1, .aperture_diameter_mm = 30, .is_stop = true},
      {.radius_mm = 40, .thickness_mm = 5, .n_d = 1.6, .aperture_diameter_mm = 30},
      {.radius_mm = 0, .n_d = 1, .aperture_diameter_mm = 30, .aspheric = {a4, a6}},
  };
  LensSystem lens(p);
  for (double h : {1.0, 6.0, 12.0}) {
    auto out = lens.trace({{0, h, 20}, {0, 0, -1}}, TraceFrom::scene);
    ASSERT_TRUE(out);
    double r = std::hypot(out->origin.x, out->origin.y);
    EXPECT_NEAR(out->origin.z, -(a4 * std::pow(r, 4) + a6 * std::pow(r, 6)), 1e-10) << h;
  }
}

// N-BK7's catalogue indices (Schott): n_d 1.51680, n_F 1.52238, n_C 1.51432, V_d 64.17.
constexpr double kBk7_d = 1.5168, kBk7_F = 1.52238, kBk7_C = 1.51432, kBk7_abbe = 64.17;

// A biconvex N-BK7 singlet behind a stop 12 mm in front of it: with the stop away from the lens
// the chief ray crosses the lens off centre, so the image height depends on the wavelength.
LensPrescription singlet() {
  LensPrescription p;
  p.name = "singlet";
  p.surfaces = {
      {.radius_mm = 0, .thickness_mm = 12, .n_d = 1, .aperture_diameter_mm = 6, .is_stop = true},
      {.radius_mm = 60,
       .thickness_mm = 5,
       .n_d = kBk7_d,
       .abbe_number = kBk7_abbe,
       .aperture_diameter_mm = 40},
      {.radius_mm = -60, .n_d = 1, .aperture_diameter_mm = 40},
  };
  return p;
}

double catalogue_index(double wavelength_nm) {
  return wavelength_nm == kWavelengthF_nm   ? kBk7_F
         : wavelength_nm == kWavelengthC_nm ? kBk7_C
                                            : kBk7_d;
}

// The paraxial image height of a chief ray at angle θ (tangent as the paraxial angle) on a
// sensor at distance `sensor_mm` behind the rear vertex, at the catalogue index of one line.
double paraxial_chief_height(const LensPrescription& p, double theta, double wavelength_nm,
                             double sensor_mm) {
  double y = 0, nu = std::tan(theta), n = 1;
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    const LensSurface& s = p.surfaces[i];
    double n_after = s.n_d == 1 ? 1 : catalogue_index(wavelength_nm);
    if (s.radius_mm != 0) nu -= y * (n_after - n) / s.radius_mm;
    n = n_after;
    y += (i + 1 < p.surfaces.size() ? s.thickness_mm : sensor_mm) * nu / n;
  }
  return y;
}

TEST(LensSystem, LateralColourOfASingletMatchesParaxialPrediction) {
  LensSystem lens(singlet());
  const double sensor_mm = lens.back_focal_distance_mm();  // the d line's focus
  // The image corner of a sensor whose half-diagonal sees 8°.
  const double theta = 8 * kDegrees;
  auto height = [&](double wavelength_nm) {
    // The chief ray: from the scene at θ through the stop's centre (the first surface).
    Vector3d d(0, std::sin(theta), -std::cos(theta));  // rising, as the paraxial ray's +tan θ
    Point3d stop_centre(0, 0, lens.front_z_mm());
    TraceOptions options;
    options.wavelength_nm = wavelength_nm;
    auto out = lens.trace({stop_centre - d * 50.0, d}, TraceFrom::scene, options);
    EXPECT_TRUE(out);
    return out ? height_at(*out, -sensor_mm) : 0.0;
  };
  double traced = height(kWavelengthF_nm) - height(kWavelengthC_nm);
  double predicted = paraxial_chief_height(singlet(), theta, kWavelengthF_nm, sensor_mm) -
                     paraxial_chief_height(singlet(), theta, kWavelengthC_nm, sensor_mm);
  EXPECT_GT(std::abs(predicted), 0.005);  // a measurable fringe: several micrometres
  EXPECT_NEAR(traced, predicted, 0.05 * std::abs(predicted))
      << "lateral colour F − C: traced " << traced << " mm, paraxial " << predicted << " mm";
}

TEST(LensSystem, LongitudinalColourOfASingletMatchesParaxialPrediction) {
  LensSystem lens(singlet());
  auto focus = [&](double wavelength_nm) {
    TraceOptions options;
    options.wavelength_nm = wavelength_nm;
    auto out = parallel_ray(lens, 0.01, options);
    EXPECT_TRUE(out);
    return out ? -axis_crossing_z(*out) : 0.0;
  };
  auto at = [](double wavelength_nm) {
    return [wavelength_nm](double, double) { return catalogue_index(wavelength_nm); };
  };
  double predicted = test::paraxial_optics(singlet(), at(kWavelengthF_nm)).bfd_mm -
                     test::paraxial_optics(singlet(), at(kWavelengthC_nm)).bfd_mm;
  double traced = focus(kWavelengthF_nm) - focus(kWavelengthC_nm);
  EXPECT_LT(predicted, -0.5);  // blue focuses closer to the lens
  EXPECT_NEAR(traced, predicted, 0.05 * std::abs(predicted));
}

TEST(LensSystem, DispersionFollowsTheAbbeNumber) {
  // The Cauchy fit keeps n_d and makes n_F − n_C = (n_d − 1) / V_d; against N-BK7's catalogue
  // n_F and n_C to a few 1e-5.
  EXPECT_DOUBLE_EQ(refractive_index(kBk7_d, kBk7_abbe, kWavelengthD_nm), kBk7_d);
  EXPECT_NEAR(refractive_index(kBk7_d, kBk7_abbe, kWavelengthF_nm), kBk7_F, 1e-4);
  EXPECT_NEAR(refractive_index(kBk7_d, kBk7_abbe, kWavelengthC_nm), kBk7_C, 1e-4);
  EXPECT_EQ(refractive_index(kBk7_d, 0, 450), kBk7_d);  // no Abbe number: no dispersion
}

TEST(LensSystem, TotalInternalReflectionAndClearAperturesStopRays) {
  auto lens = builtin_lens("double-gauss-50mm");
  // Beyond the front element's clear aperture.
  EXPECT_FALSE(parallel_ray(*lens, 13.0));
  // A flat front and a strongly curved rear (radius 6 mm, n 1.67): a parallel ray at height h
  // meets the rear sphere at incidence sin i = h / 6, beyond the critical angle (sin = 1 / 1.67)
  // from h = 3.59 mm on, and is reflected back inside.
  LensPrescription p;
  p.name = "hemisphere";
  p.surfaces = {
      {.radius_mm = 0, .thickness_mm = 1, .n_d = 1, .aperture_diameter_mm = 11.9, .is_stop = true},
      {.radius_mm = 0, .thickness_mm = 6, .n_d = 1.67, .aperture_diameter_mm = 11.9},
      {.radius_mm = -6, .n_d = 1, .aperture_diameter_mm = 11.9},
  };
  LensSystem hemisphere(p);
  EXPECT_TRUE(parallel_ray(hemisphere, 3.5));
  EXPECT_FALSE(parallel_ray(hemisphere, 3.7));
}

}  // namespace
}  // namespace obscura

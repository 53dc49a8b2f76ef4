#include "obscura/camera/focused_lens_system.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "obscura/math/error.h"
#include "obscura/math/golden_section.h"
#include "obscura/math/number_text.h"
#include "obscura/math/safe_index.h"

namespace obscura {

namespace {

constexpr double kMillimetresPerMetre = 1000;
// Exit-pupil bounds: film radii sampled from the centre to the sensor's corner, and the grid of
// points tried on the rear vertex plane for each (a square 1.5× the rear element's radius, since
// oblique rays cross that plane beyond the element's rim).
constexpr int kPupilRadii = 64;
constexpr int kPupilGrid = 64;
constexpr double kPupilSearchScale = 1.5;

Point2d rotate(Point2d p, double cos_a, double sin_a) {
  return {p.x * cos_a - p.y * sin_a, p.x * sin_a + p.y * cos_a};
}

// The z where a meridional ray (in the y = 0 plane, or any plane through the axis) crosses the
// axis; NaN when parallel to it.
double axis_crossing_z(const LensRay& ray, double height, double slope_component) {
  if (slope_component == 0) return std::numeric_limits<double>::quiet_NaN();
  return ray.origin.z - height / slope_component * ray.direction.z;
}

}  // namespace

bool operator==(const LensSettings& a, const LensSettings& b) {
  return a.focus_distance_m == b.focus_distance_m && a.f_number == b.f_number &&
         a.aperture.blades == b.aperture.blades &&
         a.aperture.rotation_degrees == b.aperture.rotation_degrees &&
         a.sensor_width_mm == b.sensor_width_mm && a.sensor_height_mm == b.sensor_height_mm;
}

FocusedLensSystem::FocusedLensSystem(std::shared_ptr<const LensSystem> lens,
                                     const LensSettings& settings)
    : lens_(std::move(lens)), settings_(settings) {
  if (!lens_) throw Error("camera.lens", "no lens system");
  const double widest = lens_->f_number();
  f_number_ = settings.f_number > 0 ? settings.f_number : widest;
  // A hair of slack: the design's own f-number printed with few digits must still be accepted.
  if (!(f_number_ >= widest * (1 - 1e-3)) || !std::isfinite(f_number_))
    throw Error("camera.f_number", "lens '" + lens_->name() + "' opens to f/" +
                                       number_text(widest) + " at most; got f/" +
                                       number_text(settings.f_number));
  f_number_ = std::max(f_number_, widest);
  // Stopping down scales the stop: the entrance pupil, its image, scales with it.
  stop_ = {lens_->stop_radius_mm() * widest / f_number_, settings.aperture};
  if (!(settings.sensor_width_mm > 0) || !(settings.sensor_height_mm > 0))
    throw Error("camera.sensor_width_mm", "must be positive; got " +
                                              number_text(settings.sensor_width_mm) + " x " +
                                              number_text(settings.sensor_height_mm));
  if (!(settings.focus_distance_m > 0))
    throw Error("camera.focus_distance_m",
                "must be positive; got " + number_text(settings.focus_distance_m));
  film_distance_mm_ = solve_film_distance(settings.focus_distance_m * kMillimetresPerMetre);
  max_film_radius_mm_ = 0.5 * std::hypot(settings.sensor_width_mm, settings.sensor_height_mm);
  compute_pupil_bounds();
}

// Focusing moves the whole lens: the film distance d that images the axial point at distance S
// in front of the sensor onto it. First Newton's thick-lens equation x·x' = f², with x the
// object's distance from the front focal point and x' = d − BFD the image's from the rear one:
// (d − BFD)·(S − d − z_F) = f², a quadratic in d. Then the exact paraxial focus, by tracing a
// near-axial ray from the object point and moving the lens until it crosses the axis on the
// sensor (secant steps). Last, the sharpest focus near it (best_focus).
double FocusedLensSystem::solve_film_distance(double focus_distance_mm) const {
  const LensSystem& lens = *lens_;
  const double bfd = lens.back_focal_distance_mm();
  if (std::isinf(focus_distance_mm)) return best_focus(focus_distance_mm, bfd);
  const double f = lens.effective_focal_length_mm();
  const double front_focus_z = lens.front_z_mm() + lens.front_focal_distance_mm();
  const double a = focus_distance_mm - front_focus_z;
  const double discriminant = (a - bfd) * (a - bfd) - 4 * f * f;
  const double closest_m = (front_focus_z + bfd + 2 * f) / kMillimetresPerMetre;
  if (!(a - bfd > 0) || discriminant < 0)
    throw Error("camera.focus_distance_m",
                "lens '" + lens.name() + "' cannot focus at " +
                    number_text(focus_distance_mm / kMillimetresPerMetre) +
                    " m from the sensor; the closest is about " + number_text(closest_m) + " m");
  double d = 0.5 * ((a + bfd) - std::sqrt(discriminant));
  // g(d): where the near-axial ray from the object crosses the axis, relative to the sensor.
  TraceOptions construction;
  construction.apertures = false;
  const double h = 1e-4 * lens.stop_radius_mm();
  auto miss = [&](double film_distance) {
    double object_z = focus_distance_mm - film_distance;
    Vector3d towards(0, h, lens.front_z_mm() - object_z);
    auto out =
        lens.trace({{0, 0, object_z}, towards / length(towards)}, TraceFrom::scene, construction);
    if (!out) return std::numeric_limits<double>::quiet_NaN();
    return axis_crossing_z(*out, out->origin.y, out->direction.y) + film_distance;
  };
  double d0 = d, g0 = miss(d0);
  double d1 = d0 + 1e-3 * f, g1 = miss(d1);
  for (int i = 0; i < 30 && std::isfinite(g0) && std::isfinite(g1) && g1 != g0; ++i) {
    double d2 = d1 - g1 * (d1 - d0) / (g1 - g0);
    d0 = d1, g0 = g1;
    d1 = d2, g1 = miss(d1);
    if (std::abs(d1 - d0) < 1e-10 * f) break;
  }
  if (std::isfinite(g1) && std::abs(g1) < 1e-6 * f && d1 > 0) d = d1;
  return best_focus(focus_distance_mm, d);
}

// Wide open, a real lens's zones focus at different distances (spherical aberration): the
// sharpest image is not at the paraxial focus. The film distance near `paraxial_mm` with the
// smallest RMS spot of the axial point, by golden-section search on a meridional fan of rays over
// the stop's opening, each weighted by its zone's circumference (the fan stands for the disk).
double FocusedLensSystem::best_focus(double focus_distance_mm, double paraxial_mm) const {
  const LensSystem& lens = *lens_;
  const double reach = 0.5 * lens.prescription().surfaces.front().aperture_diameter_mm;
  TraceOptions options;
  options.stop = StopOpening{stop_.radius_mm, Aperture{}};
  constexpr int kFan = 96;
  auto rms_spot = [&](double film_distance) {
    const double object_z = std::isinf(focus_distance_mm) ? 0 : focus_distance_mm - film_distance;
    double sum = 0, weights = 0;
    for (int i = 0; i < kFan; ++i) {
      double h = reach * (i + 0.5) / kFan;
      LensRay ray;
      if (std::isinf(focus_distance_mm)) {
        ray = {{0, h, lens.front_z_mm() + 1}, {0, 0, -1}};
      } else {
        Vector3d d = Point3d(0, h, lens.front_z_mm()) - Point3d(0, 0, object_z);
        ray = {{0, 0, object_z}, d / length(d)};
      }
      auto out = lens.trace(ray, TraceFrom::scene, options);
      if (!out) continue;
      double t = (-film_distance - out->origin.z) / out->direction.z;
      double y = out->origin.y + t * out->direction.y;
      sum += h * y * y, weights += h;
    }
    return weights > 0 ? std::sqrt(sum / weights) : std::numeric_limits<double>::infinity();
  };
  // The spot is centred on the axis by symmetry; search ±2 % of the focal length.
  const double span = 0.02 * lens.effective_focal_length_mm();
  double best = golden_section_minimum(rms_spot, paraxial_mm - span, paraxial_mm + span, 60);
  return std::isfinite(rms_spot(best)) && best > 0 ? best : paraxial_mm;
}

bool FocusedLensSystem::passes(double film_radius_mm, Point2d pupil_point_mm) const {
  Point3d film(film_radius_mm, 0, -film_distance_mm_);
  Vector3d d = Point3d(pupil_point_mm.x, pupil_point_mm.y, 0) - film;
  TraceOptions options;
  options.stop = StopOpening{stop_.radius_mm, Aperture{}};  // the circle the blades fit in
  return lens_->trace({film, d / length(d)}, TraceFrom::film, options).has_value();
}

// For each film radius r_k, the bounding rectangle of the grid points on the rear vertex plane
// that light passes through; interval k between r_k and r_k+1 takes the union of both ends,
// grown by a grid cell, so that the pupil of every film point in it lies inside (as the pupil
// moves and changes shape smoothly with r).
void FocusedLensSystem::compute_pupil_bounds() {
  const double extent = kPupilSearchScale * lens_->rear_aperture_radius_mm();
  const double cell = 2 * extent / kPupilGrid;
  std::vector<PupilBounds> at_radius(kPupilRadii + 1);
  for (int k = 0; k <= kPupilRadii; ++k) {
    double r = max_film_radius_mm_ * k / kPupilRadii;
    PupilBounds& b = at_radius[size_t(k)];
    b = {extent, -extent, extent, -extent};
    for (int j = 0; j < kPupilGrid; ++j)
      for (int i = 0; i < kPupilGrid; ++i) {
        Point2d p(-extent + (i + 0.5) * cell, -extent + (j + 0.5) * cell);
        if (!passes(r, p)) continue;
        b.x_min = std::min(b.x_min, p.x), b.x_max = std::max(b.x_max, p.x);
        b.y_min = std::min(b.y_min, p.y), b.y_max = std::max(b.y_max, p.y);
      }
  }
  bounds_.resize(kPupilRadii);
  for (int k = 0; k < kPupilRadii; ++k) {
    const PupilBounds &a = at_radius[size_t(k)], &b = at_radius[size_t(k) + 1];
    PupilBounds u;
    if (a.empty() && b.empty()) {
      bounds_[size_t(k)] = u;
      continue;
    }
    u = a.empty() ? b : a;
    if (!b.empty()) {
      u.x_min = std::min(u.x_min, b.x_min), u.x_max = std::max(u.x_max, b.x_max);
      u.y_min = std::min(u.y_min, b.y_min), u.y_max = std::max(u.y_max, b.y_max);
    }
    bounds_[size_t(k)] = {u.x_min - cell, u.x_max + cell, u.y_min - cell, u.y_max + cell};
  }
}

PupilBounds FocusedLensSystem::pupil_bounds(double film_radius_mm) const {
  // NaN-safe (math/safe_index.h): int(NaN) or int(1e300) would be undefined.
  double k = clamp_or_low(film_radius_mm / max_film_radius_mm_ * kPupilRadii, 0.0,
                          double(kPupilRadii - 1));
  return bounds_[size_t(k)];
}

LensCameraRay FocusedLensSystem::to_camera(const LensRay& ray) const {
  LensCameraRay out;
  out.origin = Point3d(ray.origin.x / kMillimetresPerMetre, ray.origin.y / kMillimetresPerMetre,
                       -(ray.origin.z + film_distance_mm_) / kMillimetresPerMetre);
  out.direction = Vector3d(ray.direction.x, ray.direction.y, -ray.direction.z);
  return out;
}

std::optional<LensCameraRay> FocusedLensSystem::ray(Point2d image_mm, Point2d u,
                                                    double wavelength_nm) const {
  // 1. The film point: the image point, inverted (a real lens turns the image upside down).
  const Point2d film(-image_mm.x, -image_mm.y);
  const double r = std::sqrt(film.x * film.x + film.y * film.y);
  // 2. A point of the exit pupil's bounds for this radius, turned to the film point's azimuth.
  const PupilBounds b = pupil_bounds(r);
  if (b.empty()) return std::nullopt;
  const double cos_a = r > 0 ? film.x / r : 1, sin_a = r > 0 ? film.y / r : 0;
  Point2d p = rotate({b.x_min + u.x * (b.x_max - b.x_min), b.y_min + u.y * (b.y_max - b.y_min)},
                     cos_a, sin_a);
  // 3. Through the lens, from the film out into the scene.
  Point3d origin(film.x, film.y, -film_distance_mm_);
  Vector3d towards = Point3d(p.x, p.y, 0) - origin;
  const double distance = length(towards);
  TraceOptions options;
  options.wavelength_nm = wavelength_nm;
  options.stop = stop_;
  std::optional<LensRay> out = lens_->trace({origin, towards / distance}, TraceFrom::film, options);
  if (!out) return std::nullopt;
  // 4. Its share of the irradiance (see the header), relative to the thin lens at f/N.
  const double cos_theta = film_distance_mm_ / distance;
  const double cos2 = cos_theta * cos_theta;
  LensCameraRay ray = to_camera(*out);
  ray.weight = cos2 * cos2 * b.area() / (film_distance_mm_ * film_distance_mm_) * 4 * f_number_ *
               f_number_ / std::numbers::pi;
  return ray;
}

// The chief ray from film point (r, 0): aimed at the rear vertex plane at the height a whose
// ray crosses the stop's plane on the axis, found by secant steps on a (from a = 0, the
// direction a pinhole at the rear vertex would take).
std::optional<LensRay> FocusedLensSystem::chief_ray_lens(double film_radius_mm,
                                                         double wavelength_nm) const {
  const Point3d film(film_radius_mm, 0, -film_distance_mm_);
  Point3d at_stop;
  TraceOptions construction;
  construction.apertures = false;
  construction.wavelength_nm = wavelength_nm;
  construction.at_stop = &at_stop;
  auto aim = [&](double a) -> std::optional<LensRay> {
    Vector3d d = Point3d(a, 0, 0) - film;
    return lens_->trace({film, d / length(d)}, TraceFrom::film, construction);
  };
  if (film_radius_mm == 0) return aim(0);
  const double step = 1e-3 * lens_->stop_radius_mm();
  double a0 = 0, a1 = -step;
  auto r0 = aim(a0);
  double h0 = at_stop.x;
  auto r1 = aim(a1);
  double h1 = at_stop.x;
  for (int i = 0; i < 60 && r0 && r1; ++i) {
    if (std::abs(h1) < 1e-12 * lens_->stop_radius_mm() + 1e-14) return r1;
    if (h1 == h0) break;
    double a2 = a1 - h1 * (a1 - a0) / (h1 - h0);
    a0 = a1, h0 = h1, r0 = r1;
    a1 = a2, r1 = aim(a1), h1 = at_stop.x;
  }
  return std::nullopt;
}

std::optional<LensCameraRay> FocusedLensSystem::chief_ray(Point2d image_mm,
                                                          double wavelength_nm) const {
  const Point2d film(-image_mm.x, -image_mm.y);
  const double r = std::hypot(film.x, film.y);
  std::optional<LensRay> meridional = chief_ray_lens(r, wavelength_nm);
  if (!meridional) return std::nullopt;
  // Turn the meridional ray (in the x–z plane) to the film point's azimuth.
  const double cos_a = r > 0 ? film.x / r : 1, sin_a = r > 0 ? film.y / r : 0;
  Point2d o = rotate({meridional->origin.x, meridional->origin.y}, cos_a, sin_a);
  Point2d d = rotate({meridional->direction.x, meridional->direction.y}, cos_a, sin_a);
  return to_camera({{o.x, o.y, meridional->origin.z}, {d.x, d.y, meridional->direction.z}});
}

// The object's height ρ (lens space, at its z) against the signed film radius whose chief ray
// reaches that plane at ρ; solved by secant steps from the paraxial guess r = −f·ρ / distance.
std::optional<Point2d> FocusedLensSystem::image_point_of(Point3d camera_point) const {
  const double x = camera_point.x * kMillimetresPerMetre, y = camera_point.y * kMillimetresPerMetre;
  const double z = -camera_point.z * kMillimetresPerMetre - film_distance_mm_;
  if (!(z > lens_->front_z_mm())) return std::nullopt;  // not in front of the lens
  const double rho = std::hypot(x, y);
  if (rho == 0) return Point2d(0, 0);
  auto height_at_object = [&](double r) {
    auto chief = chief_ray_lens(r, kWavelengthD_nm);
    if (!chief || !(chief->direction.z > 0)) return std::numeric_limits<double>::quiet_NaN();
    return chief->origin.x + (z - chief->origin.z) / chief->direction.z * chief->direction.x;
  };
  const double f = lens_->effective_focal_length_mm();
  double r0 = -f * rho / (z - lens_->front_z_mm()), r1 = r0 * 1.001;
  r0 = std::clamp(r0, -max_film_radius_mm_ * 2, 0.0);
  double g0 = height_at_object(r0) - rho, g1 = height_at_object(r1) - rho;
  for (int i = 0; i < 60; ++i) {
    if (!std::isfinite(g0) || !std::isfinite(g1)) return std::nullopt;
    if (std::abs(g1) < 1e-9 * std::max(1.0, rho)) {
      // The sensor point at radius r1 (< 0: opposite the object) and the image point, upright.
      return Point2d(-r1 * x / rho, -r1 * y / rho);
    }
    if (g1 == g0) return std::nullopt;
    double r2 = r1 - g1 * (r1 - r0) / (g1 - g0);
    r0 = r1, g0 = g1;
    r1 = r2, g1 = height_at_object(r1) - rho;
  }
  return std::nullopt;
}

std::shared_ptr<const FocusedLensSystem> focused_lens_system(
    const std::shared_ptr<const LensSystem>& lens, const LensSettings& settings) {
  struct Cached {
    std::shared_ptr<const LensSystem> lens;  // held, so its address is not reused meanwhile
    LensSettings settings;
    std::shared_ptr<const FocusedLensSystem> focused;
  };
  thread_local Cached cached;
  if (!cached.focused || cached.lens != lens || !(cached.settings == settings)) {
    cached.focused = std::make_shared<const FocusedLensSystem>(lens, settings);
    cached.lens = lens;
    cached.settings = settings;
  }
  return cached.focused;
}

}  // namespace obscura

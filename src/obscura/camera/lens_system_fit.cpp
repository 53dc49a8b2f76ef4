#include "obscura/camera/lens_system_fit.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include <tbb/parallel_for.h>

#include "obscura/math/error.h"
#include "obscura/math/golden_section.h"
#include "obscura/math/least_squares.h"

namespace obscura {

namespace {

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;
constexpr double kMillimetresPerMetre = 1000;
// Beyond this field angle only a fisheye model can describe the lens (tan θ runs off to ∞).
constexpr double kFisheyeFieldDegrees = 80;
// A rectilinear fit this good (pixels) is kept without trying the fisheye model.
constexpr double kGoodEnoughPx = 0.01;

// The measured heights, as fractions of the edge's, at table positions s ∈ [0, 1]:
// x = s·(1 + a·(1 − s)), three times as dense at the edge as at the centre (a = ½), where the
// illumination drops fastest (a rim cutting the pupil, a fisheye's image circle). And back:
// s = ((1 + a) − √((1 + a)² − 4a·x)) / 2a.
constexpr double kEdgeCrowding = 0.5;
double height_fraction(double s) {
  return s * (1 + kEdgeCrowding * (1 - s));
}
double table_position(double x) {
  const double b = 1 + kEdgeCrowding;
  return (b - std::sqrt(std::max(0.0, b * b - 4 * kEdgeCrowding * x))) / (2 * kEdgeCrowding);
}

// The image point at height h along the diagonal towards the upper-right corner.
struct Diagonal {
  double x = 0, y = 0;  // unit direction
  Point2d at(double h) const { return {h * x, h * y}; }
};

struct ChiefRay {
  double direction_angle_rad = 0;
  double pupil_distance_mm = std::numeric_limits<double>::quiet_NaN();  // NaN on the axis
  double focus_plane_height_mm = 0;  // 0 when focused at infinity
};

// The object-side chief ray of image point `image`: its angle from the axis, where its line
// crosses the axis (the point nearest the axis: in its meridional plane the two meet) and its
// distance from the axis on the plane of focus.
std::optional<ChiefRay> chief_ray(const FocusedLensSystem& lens, Point2d image) {
  auto ray = lens.chief_ray(image);
  if (!ray || !(ray->direction.z < 0)) return std::nullopt;
  const Vector3d& d = ray->direction;
  const Point3d& o = ray->origin;
  ChiefRay out;
  const double radial2 = d.x * d.x + d.y * d.y;
  out.direction_angle_rad = std::atan2(std::sqrt(radial2), -d.z);
  if (radial2 > 0) {
    const double t = -(o.x * d.x + o.y * d.y) / radial2;
    out.pupil_distance_mm = -(o.z + t * d.z) * kMillimetresPerMetre;
  }
  const double focus_m = lens.settings().focus_distance_m;
  if (std::isfinite(focus_m)) {
    const double t = (-focus_m - o.z) / d.z;
    out.focus_plane_height_mm = std::hypot(o.x + t * d.x, o.y + t * d.y) * kMillimetresPerMetre;
  }
  return out;
}

// The mean of the traced ray weights at image point `image` over a grid × grid of pupil samples
// at the cells' centres (blocked rays count 0): what the tracer's pixel converges to.
double mean_ray_weight(const FocusedLensSystem& lens, Point2d image, int grid) {
  double sum = 0;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i)
      if (auto r = lens.ray(image, {(i + 0.5) / grid, (j + 0.5) / grid})) sum += r->weight;
  return sum / (double(grid) * grid);
}

// Whether some of the grid's rays at `image` pass the lens.
bool lit(const FocusedLensSystem& lens, Point2d image, int grid) {
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i)
      if (lens.ray(image, {(i + 0.5) / grid, (j + 0.5) / grid})) return true;
  return false;
}

// One candidate model's radial map h(θ) = Σ a_i · basis_i(θ), with a_0 the focal length.
struct RadialFit {
  LensModel model;
  double focal_length_mm = 0;
  double max_error_mm = std::numeric_limits<double>::infinity(), rms_error_mm = 0;
};

// Least squares of h over the measured field in the odd powers `powers` of `variable(θ)`.
RadialFit fit_odd_powers(const LensMeasurement& m, int powers,
                         const std::function<double(double)>& variable) {
  LeastSquaresProblem problem;
  problem.columns = powers;
  auto basis = [&](double theta) {
    const double v = variable(theta);
    std::vector<double> row(static_cast<size_t>(powers));
    double p = v;
    for (int i = 0; i < powers; ++i, p *= v * v) row[size_t(i)] = p;
    return row;
  };
  for (size_t i = 1; i < m.field.size(); ++i)
    problem.add_row(basis(m.field[i].field_angle_rad), m.field[i].image_height_mm);
  std::vector<double> a = solve_least_squares(problem);
  RadialFit fit;
  fit.focal_length_mm = a[0];
  double sum = 0;
  fit.max_error_mm = 0;
  for (size_t i = 1; i < m.field.size(); ++i) {
    std::vector<double> row = basis(m.field[i].field_angle_rad);
    double h = 0;
    for (int k = 0; k < powers; ++k) h += a[size_t(k)] * row[size_t(k)];
    const double e = h - m.field[i].image_height_mm;
    fit.max_error_mm = std::max(fit.max_error_mm, std::abs(e));
    sum += e * e;
  }
  fit.rms_error_mm = std::sqrt(sum / double(m.field.size() - 1));
  // The coefficients relative to the focal length: the models' k's.
  std::vector<double> k(a.begin() + 1, a.end());
  for (double& v : k) v /= a[0];
  k.resize(4, 0);
  if (powers == 4)
    fit.model = PinholeDistortion{.k1 = k[0], .k2 = k[1], .k3 = k[2]};
  else
    fit.model = KannalaBrandt{k[0], k[1], k[2], k[3]};
  return fit;
}

// The field angle the fitted projection gives image height `height_mm` (its field limit where
// the height is beyond the model's reach).
double model_field_angle(const LensMap& map, double focal_length_mm, double height_mm) {
  auto ray = map.inverse({height_mm / focal_length_mm, 0});
  if (!ray) return map.max_field_angle();
  return std::atan2(std::hypot(ray->x, ray->y), ray->z);
}

// How far, in image millimetres per unit of (axial shift / object distance), a point's image
// moves when the centre of projection moves along the axis: the shift turns the point's
// direction by (shift / distance)·sin θ, and the image moves dh/dθ per radian.
std::vector<double> parallax_weights(const std::vector<LensFieldPoint>& field) {
  std::vector<double> w(field.size(), 0);
  for (size_t i = 1; i + 1 < field.size(); ++i) {
    const double dh = field[i + 1].image_height_mm - field[i - 1].image_height_mm;
    const double dtheta = field[i + 1].direction_angle_rad - field[i - 1].direction_angle_rad;
    w[i] = std::sin(field[i].direction_angle_rad) * dh / dtheta;
  }
  if (field.size() > 2) {  // the edge: the last interval's slope
    const size_t n = field.size() - 1;
    const double dh = field[n].image_height_mm - field[n - 1].image_height_mm;
    const double dtheta = field[n].direction_angle_rad - field[n - 1].direction_angle_rad;
    w[n] = std::sin(field[n].direction_angle_rad) * dh / dtheta;
  }
  return w;
}

// The point on the axis (mm in front of the sensor) that minimizes the largest image
// displacement max_i w_i·|z_i − c| between the chief rays' axis crossings z_i and it: a convex
// function of c, minimized by golden-section search between the crossings' extremes.
double centre_of_projection(const std::vector<LensFieldPoint>& field, double paraxial_mm) {
  const std::vector<double> w = parallax_weights(field);
  double lo = paraxial_mm, hi = paraxial_mm;
  for (const LensFieldPoint& p : field)
    if (std::isfinite(p.pupil_distance_mm))
      lo = std::min(lo, p.pupil_distance_mm), hi = std::max(hi, p.pupil_distance_mm);
  auto worst = [&](double c) {
    double e = 0;
    for (size_t i = 0; i < field.size(); ++i)
      if (std::isfinite(field[i].pupil_distance_mm) && std::isfinite(w[i]))
        e = std::max(e, std::abs(w[i] * (field[i].pupil_distance_mm - c)));
    return e;
  };
  return golden_section_minimum(worst, lo, hi, 80, 1e-9 * (1 + std::abs(hi)));
}

}  // namespace

LensMeasurement measure_lens_system(const FocusedLensSystem& lens, int heights, int pupil_grid) {
  if (heights < 8 || pupil_grid < 1)
    throw Error("lens fit", "needs at least 8 image heights and one pupil sample");
  const LensSettings& s = lens.settings();
  const double half_w = 0.5 * s.sensor_width_mm, half_h = 0.5 * s.sensor_height_mm;
  const double corner = std::hypot(half_w, half_h);
  const Diagonal diagonal{half_w / corner, half_h / corner};
  const std::string where = "lens '" + lens.lens().name() + "'";

  LensMeasurement m;
  // 1. Near the axis: the paraxial focal length and entrance pupil.
  const double tiny = 1e-4 * corner;
  auto paraxial = chief_ray(lens, diagonal.at(tiny));
  if (!paraxial || !(paraxial->direction_angle_rad > 0))
    throw Error(where, "no chief ray leaves the lens near the axis");
  m.paraxial_focal_length_mm = tiny / std::tan(paraxial->direction_angle_rad);
  m.entrance_pupil_distance_mm = paraxial->pupil_distance_mm;
  if (!lit(lens, {0, 0}, pupil_grid)) throw Error(where, "no light reaches the image centre");

  // 2. The edge: the corner, or the largest height that still has light and a chief ray.
  auto reached = [&](double h) {
    return chief_ray(lens, diagonal.at(h)) && lit(lens, diagonal.at(h), pupil_grid);
  };
  m.edge_height_mm = corner;
  if (!reached(corner)) {
    double lo = 0, hi = corner;
    for (int i = 0; i < 40; ++i) {
      double mid = 0.5 * (lo + hi);
      (reached(mid) ? lo : hi) = mid;
    }
    m.edge_height_mm = lo;
    m.image_circle = true;
    if (!(lo > tiny)) throw Error(where, "no chief ray leaves the lens beyond the axis");
  }

  // 3. The field out to the edge (each height on its own: in parallel).
  m.field.resize(size_t(heights));
  std::vector<ChiefRay> chiefs(static_cast<size_t>(heights));
  std::vector<bool> missing(size_t(heights), false);
  tbb::parallel_for(0, heights, [&](int i) {
    LensFieldPoint& p = m.field[size_t(i)];
    p.image_height_mm = m.edge_height_mm * height_fraction(double(i) / (heights - 1));
    const Point2d image = diagonal.at(p.image_height_mm);
    auto chief = i == 0 ? ChiefRay{0, m.entrance_pupil_distance_mm, 0} : chief_ray(lens, image);
    if (!chief) {
      missing[size_t(i)] = true;
      return;
    }
    chiefs[size_t(i)] = *chief;
    p.direction_angle_rad = chief->direction_angle_rad;
    p.pupil_distance_mm = chief->pupil_distance_mm;
    p.relative_illumination = mean_ray_weight(lens, image, pupil_grid);
  });
  for (int i = 0; i < heights; ++i)
    if (missing[size_t(i)])
      throw Error(where, "no chief ray at image height " +
                             std::to_string(m.field[size_t(i)].image_height_mm) + " mm");

  // 4. The centre of projection and the field angles seen from it.
  m.centre_of_projection_mm = centre_of_projection(m.field, m.entrance_pupil_distance_mm);
  const double focus_mm = s.focus_distance_m * kMillimetresPerMetre;
  for (size_t i = 0; i < m.field.size(); ++i)
    m.field[i].field_angle_rad =
        std::isfinite(focus_mm)
            ? std::atan2(chiefs[i].focus_plane_height_mm, focus_mm - m.centre_of_projection_mm)
            : m.field[i].direction_angle_rad;

  // 5. The traced field of view: twice the chief ray's angle at each edge (or the circle).
  auto full_angle = [&](double h) {
    h = std::min(h, m.edge_height_mm);
    auto chief = chief_ray(lens, diagonal.at(h));
    return chief ? 2 * chief->direction_angle_rad * kDegreesPerRadian : 0.0;
  };
  m.fov_degrees = {full_angle(half_w), full_angle(half_h), full_angle(corner)};
  return m;
}

double LensSystemFit::relative_illumination(double image_height_mm) const {
  const std::vector<LensFieldPoint>& f = measured.field;
  const double edge = measured.edge_height_mm;
  if (f.empty() || !(image_height_mm <= edge * (1 + 1e-12))) return 0;
  const double t =
      table_position(std::clamp(image_height_mm / edge, 0.0, 1.0)) * double(f.size() - 1);
  const size_t i = std::min(size_t(t), f.size() - 2);
  const double w = t - double(i);
  return (1 - w) * f[i].relative_illumination + w * f[i + 1].relative_illumination;
}

LensSystemFit fit_lens_system(const FocusedLensSystem& lens, int width_px, int height_px,
                              const LensFitSettings& settings) {
  if (width_px < 1 || height_px < 1)
    throw Error("lens fit", "needs a film of at least one pixel; got " + std::to_string(width_px) +
                                " x " + std::to_string(height_px));
  const LensSettings& s = lens.settings();
  LensSystemFit fit;
  fit.measured = measure_lens_system(lens, settings.heights, settings.pupil_grid);
  const LensMeasurement& m = fit.measured;
  const double pitch_x = s.sensor_width_mm / width_px, pitch_y = s.sensor_height_mm / height_px;
  const double pixel_mm = std::min(pitch_x, pitch_y);
  const double edge_angle = m.field.back().field_angle_rad;

  // 1. Distortion: the rectilinear model unless the field is a fisheye's or it fits worse.
  auto projection_of = [&](const RadialFit& r) {
    CalibratedProjection p;
    p.k = {.fx = r.focal_length_mm / pitch_x,
           .fy = r.focal_length_mm / pitch_y,
           .cx = 0.5 * width_px - 0.5,
           .cy = 0.5 * height_px - 0.5};
    p.width_px = width_px;
    p.height_px = height_px;
    p.lens = r.model;
    if (m.image_circle) p.max_field_angle_degrees = edge_angle * kDegreesPerRadian;
    return p;
  };
  // A model is usable when its map stays one-to-one out to the edge's field angle.
  auto usable = [&](const RadialFit& r) {
    if (!(r.focal_length_mm > 0) || !std::isfinite(r.max_error_mm)) return false;
    CalibratedProjection p = projection_of(r);
    try {
      validate(p);
    } catch (const Error&) {
      return false;
    }
    return LensMap(p.lens, max_field_angle_rad(p)).max_field_angle() >= edge_angle * (1 - 1e-9);
  };
  std::optional<RadialFit> chosen;
  if (edge_angle * kDegreesPerRadian < kFisheyeFieldDegrees) {
    RadialFit rectilinear = fit_odd_powers(m, 4, [](double theta) { return std::tan(theta); });
    if (usable(rectilinear)) chosen = rectilinear;
  }
  if (!chosen || chosen->max_error_mm > kGoodEnoughPx * pixel_mm) {
    RadialFit fisheye = fit_odd_powers(m, 5, [](double theta) { return theta; });
    if (usable(fisheye) && (!chosen || fisheye.max_error_mm < chosen->max_error_mm))
      chosen = fisheye;
  }
  if (!chosen)
    throw Error("lens '" + lens.lens().name() + "'",
                "neither the pinhole nor the Kannala–Brandt model fits its distortion");
  fit.projection = projection_of(*chosen);
  fit.max_error_px = chosen->max_error_mm / pixel_mm;
  fit.rms_error_px = chosen->rms_error_mm / pixel_mm;

  // 2. The chief rays' axis crossings around the centre of projection, and what that does to
  // the image of an object off the plane of focus.
  const std::vector<double> w = parallax_weights(m.field);
  for (size_t i = 0; i < m.field.size(); ++i) {
    const double shift = m.field[i].pupil_distance_mm - m.centre_of_projection_mm;
    if (!std::isfinite(shift)) continue;
    fit.pupil_shift_mm = std::max(fit.pupil_shift_mm, std::abs(shift));
    if (std::isfinite(w[i]))
      fit.parallax_px_m =
          std::max(fit.parallax_px_m, std::abs(w[i] * shift) / pixel_mm / kMillimetresPerMetre);
  }

  // 3. The illumination table's interpolation error at the midpoints between its heights.
  if (settings.check_illumination) {
    const double corner = std::hypot(s.sensor_width_mm, s.sensor_height_mm) / 2;
    const Diagonal diagonal{0.5 * s.sensor_width_mm / corner, 0.5 * s.sensor_height_mm / corner};
    std::vector<double> errors(m.field.size() - 1);
    tbb::parallel_for(size_t(0), errors.size(), [&](size_t i) {
      const double h = 0.5 * (m.field[i].image_height_mm + m.field[i + 1].image_height_mm);
      const double traced = mean_ray_weight(lens, diagonal.at(h), settings.pupil_grid);
      errors[i] = std::abs(fit.relative_illumination(h) - traced);
    });
    fit.max_illumination_error = *std::max_element(errors.begin(), errors.end());
  }

  // 4. The fitted model's field of view.
  const LensMap map(fit.projection.lens, max_field_angle_rad(fit.projection));
  auto full_angle = [&](double h) {
    return 2 * model_field_angle(map, chosen->focal_length_mm, std::min(h, m.edge_height_mm)) *
           kDegreesPerRadian;
  };
  fit.fov_degrees = {full_angle(0.5 * s.sensor_width_mm), full_angle(0.5 * s.sensor_height_mm),
                     full_angle(std::hypot(s.sensor_width_mm, s.sensor_height_mm) / 2)};
  return fit;
}

double FittedLensCamera::relative_illumination(Point2d film_point) const {
  const FilmGeometry& film = camera.film;
  const double x = (film_point.x / film.width_px - 0.5) * sensor_mm.x;
  const double y = (0.5 - film_point.y / film.height_px) * sensor_mm.y;
  return fit.relative_illumination(std::hypot(x, y));
}

FittedLensCamera fitted_lens_camera(const Camera& camera, const LensFitSettings& settings) {
  auto* l = std::get_if<LensSystemProjection>(&camera.projection);
  if (!l)
    throw Error("camera '" + camera.name + "'",
                "only a lens-system camera has a fitted camera; this one is " +
                    std::string(projection_name(camera.projection)));
  auto focused = focused_lens_system(l->lens, camera.lens_system_settings());
  FittedLensCamera out;
  out.fit = fit_lens_system(*focused, camera.film.width_px, camera.film.height_px, settings);
  out.sensor_mm = {focused->settings().sensor_width_mm, focused->settings().sensor_height_mm};
  Camera& c = out.camera;
  c = camera;
  c.projection = out.fit.projection;
  // Sharp, exposed as the lens system is; its vignetting is the fit's table, applied apart.
  c.lens.depth_of_field = false;
  c.lens.f_number = camera.f_number();
  c.lens.aperture_diameter_mm.reset();
  c.lens.vignetting = {};
  // Moved from the sensor to the entrance pupil, along the view direction (−Z); depths (near,
  // far) are measured from there. The tracer sees nothing closer than the front element.
  const double pupil_m = out.fit.measured.centre_of_projection_mm / kMillimetresPerMetre;
  const double front_m =
      (focused->film_distance_mm() + focused->lens().front_z_mm()) / kMillimetresPerMetre;
  std::vector<AnimatedTransform::Key> keys;
  for (const AnimatedTransform::Key& key : camera.world_from_camera.keys())
    keys.push_back({key.time_s, key.transform * Transform::translate({0, 0, -pupil_m})});
  c.world_from_camera = AnimatedTransform(std::move(keys));
  c.near_m = std::max(std::max(camera.near_m, front_m) - pupil_m, 1e-4);
  c.far_m = std::max(camera.far_m - pupil_m, c.near_m * 2);
  c.validate();
  return out;
}

}  // namespace obscura

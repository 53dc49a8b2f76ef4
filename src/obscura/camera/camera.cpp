#include "obscura/camera/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "obscura/camera/camera_extent.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"
#include "obscura/math/safe_index.h"

namespace obscura {

namespace {

constexpr double kMetresPerMillimetre = 0.001;
constexpr double kMillimetresPerMetre = 1000;
constexpr double kDegreesPerRadian = 180 / 3.14159265358979323846;

// The fisheye's image circle touches the shorter side of the image; its radius in raster units
// of height (a raster x distance times pixel_aspect is in the same physical units).
double fisheye_radius(const FilmGeometry& film) {
  return 0.5 * std::min(film.width_px * film.pixel_aspect, double(film.height_px));
}

Point2d fisheye_centered_from_raster(const FilmGeometry& film, Point2d raster) {
  double r = fisheye_radius(film);
  return {(raster.x - 0.5 * film.width_px) * film.pixel_aspect / r,
          (0.5 * film.height_px - raster.y) / r};
}

Point2d raster_from_fisheye_centered(const FilmGeometry& film, Point2d c) {
  double r = fisheye_radius(film);
  return {0.5 * film.width_px + c.x * r / film.pixel_aspect, 0.5 * film.height_px - c.y * r};
}

// A calibrated camera's pixels (OpenCV's (u, v) on the calibration's image) against the film's
// raster, and the lens model's normalized image point against (u, v) through K.
Vector2d calibration_scale(const CalibratedProjection& c, const FilmGeometry& film) {
  if (c.width_px == 0) return {1, 1};
  return {double(c.width_px) / film.width_px, double(c.height_px) / film.height_px};
}

Point2d lens_image_from_raster(const CalibratedProjection& c, const FilmGeometry& film,
                               Point2d raster) {
  Vector2d s = calibration_scale(c, film);
  double u = raster.x * s.x - 0.5, v = raster.y * s.y - 0.5;
  double y = (v - c.k.cy) / c.k.fy;
  return {(u - c.k.cx - c.k.skew * y) / c.k.fx, y};
}

Point2d raster_from_lens_image(const CalibratedProjection& c, const FilmGeometry& film,
                               Point2d image) {
  Vector2d s = calibration_scale(c, film);
  double u = c.k.fx * image.x + c.k.skew * image.y + c.k.cx, v = c.k.fy * image.y + c.k.cy;
  return {(u + 0.5) / s.x, (v + 0.5) / s.y};
}

// OpenCV's camera frame (Y down, Z forward) and Obscura's (Y up, looking down −Z) differ by a
// half turn about X; the map is its own inverse.
Vector3d flip_yz(Vector3d v) {
  return {v.x, -v.y, -v.z};
}

// Whether depth is measured along the optical axis (planes of constant depth) rather than as
// distance from the camera.
bool planar_depth(const Projection& p) {
  if (auto* c = std::get_if<CalibratedProjection>(&p)) return is_planar(c->lens);
  return std::holds_alternative<Perspective>(p) || std::holds_alternative<Orthographic>(p) ||
         std::holds_alternative<LensSystemProjection>(p);
}

// Inside the film rectangle, edges included, with a hair of slack so that points exactly on the
// frustum's boundary survive the rounding of tan() and friends.
bool on_film(const FilmGeometry& film, Point2d p) {
  constexpr double kSlackPx = 1e-9;
  return p.x >= -kSlackPx && p.x <= film.width_px + kSlackPx && p.y >= -kSlackPx &&
         p.y <= film.height_px + kSlackPx;
}

}  // namespace

Ray CameraRay::to_ray() const {
  Ray ray;
  ray.origin = Point3f(origin);
  ray.direction = Vector3f(direction);
  ray.t_min = float(t_min);
  ray.t_max = std::isinf(t_max) ? std::numeric_limits<float>::infinity() : float(t_max);
  ray.time = float(time_s);
  return ray;
}

void Camera::validate() const {
  std::visit(Overloaded{
                 [](const Perspective& p) { obscura::validate(p); },
                 [](const Orthographic& o) { obscura::validate(o); },
                 [](const Equirectangular&) {},
                 [](const Fisheye& f) { obscura::validate(f); },
                 [](const CalibratedProjection& c) { obscura::validate(c); },
                 [](const LensSystemProjection& l) { obscura::validate(l); },
             },
             projection);
  bool orthographic = std::holds_alternative<Orthographic>(projection);
  if (orthographic ? !(near_m >= 0) : !(near_m > 0))
    throw Error("camera.near_m", std::string("must be ") + (orthographic ? "≥ 0" : "positive") +
                                     "; got " + number_text(near_m));
  if (!(far_m > near_m))
    throw Error("camera.far_m",
                "must exceed near (" + number_text(near_m) + " m); got " + number_text(far_m));
  obscura::validate(lens, focal_length_mm());
  if (lens.depth_of_field && !std::holds_alternative<Perspective>(projection))
    throw Error("camera.depth_of_field", "needs a perspective projection; this camera is " +
                                             std::string(projection_name(projection)));
  obscura::validate(shutter);
  obscura::validate(exposure, shutter.duration_s());
  obscura::validate(film);
  validate_world_extent(*this);
  // A lens system must be able to focus where asked (and the iris open as far).
  if (auto* l = std::get_if<LensSystemProjection>(&projection))
    focused_lens_system(l->lens, lens_system_settings());
}

bool Camera::uses_lens_samples() const {
  return lens.depth_of_field || std::holds_alternative<LensSystemProjection>(projection);
}

LensSettings Camera::lens_system_settings() const {
  auto* l = std::get_if<LensSystemProjection>(&projection);
  if (!l) return {};
  return {.focus_distance_m = lens.focus_distance_m,
          .f_number = l->f_number.value_or(0),
          .aperture = lens.aperture,
          .sensor_width_mm = l->sensor_width_mm,
          .sensor_height_mm = l->sensor_width_mm / film.image_aspect()};
}

double Camera::focal_length_mm() const {
  auto* p = std::get_if<Perspective>(&projection);
  return p ? p->focal_length_mm : 0;
}

double Camera::image_distance_mm() const {
  double f = focal_length_mm();
  return lens.depth_of_field && lens.focus_breathing
             ? obscura::image_distance_mm(f, lens.focus_distance_m)
             : f;
}

Vector2d Camera::film_size_mm() const {
  auto* p = std::get_if<Perspective>(&projection);
  return p ? obscura::film_size_mm(*p, film.image_aspect()) : Vector2d();
}

ScreenWindow Camera::screen_window() const {
  if (auto* p = std::get_if<Perspective>(&projection)) {
    Vector2d size = obscura::film_size_mm(*p, film.image_aspect());
    double fitted = fitted_film_dimension_mm(*p, film.image_aspect());
    double v = image_distance_mm();
    double cx = p->lens_shift.x * fitted, cy = p->lens_shift.y * fitted;
    return {(cx - 0.5 * size.x) / v, (cx + 0.5 * size.x) / v, (cy - 0.5 * size.y) / v,
            (cy + 0.5 * size.y) / v};
  }
  if (auto* o = std::get_if<Orthographic>(&projection)) {
    double h = o->view_height_m;
    double w = o->view_width_m ? *o->view_width_m : h * film.image_aspect();
    return {-0.5 * w, 0.5 * w, -0.5 * h, 0.5 * h};
  }
  throw Error("camera.screen_window",
              "a " + std::string(projection_name(projection)) + " camera has no screen window");
}

Point2d Camera::window_from_raster(Point2d raster) const {
  ScreenWindow w = screen_window();
  return {w.x_min + raster.x / film.width_px * (w.x_max - w.x_min),
          w.y_max - raster.y / film.height_px * (w.y_max - w.y_min)};
}

Point2d Camera::raster_from_window(Point2d p) const {
  ScreenWindow w = screen_window();
  return {(p.x - w.x_min) / (w.x_max - w.x_min) * film.width_px,
          (w.y_max - p.y) / (w.y_max - w.y_min) * film.height_px};
}

Vector2d Camera::fov_degrees() const {
  return std::visit(
      Overloaded{
          [&](const Perspective&) {
            ScreenWindow w = screen_window();
            return Vector2d((std::atan(w.x_max) - std::atan(w.x_min)) * kDegreesPerRadian,
                            (std::atan(w.y_max) - std::atan(w.y_min)) * kDegreesPerRadian);
          },
          [](const Orthographic&) { return Vector2d(0, 0); },
          [](const Equirectangular&) { return Vector2d(360, 180); },
          [&](const Fisheye& f) {
            double r = fisheye_radius(film);
            return Vector2d(
                f.fov_degrees * std::min(1.0, film.width_px * film.pixel_aspect / (2 * r)),
                f.fov_degrees * std::min(1.0, film.height_px / (2 * r)));
          },
          [&](const CalibratedProjection& c) {
            // The angles the film's middle row and column span through the lens centre; an edge
            // the lens does not reach counts as its widest field angle.
            const LensMap& map = lens_map(c);
            auto angle_at = [&](Point2d raster) {
              auto ray = map.inverse(lens_image_from_raster(c, film, raster));
              return ray ? std::acos(std::clamp(ray->z, -1.0, 1.0)) : map.max_field_angle();
            };
            double w = film.width_px, h = film.height_px;
            Point2d centre = raster_from_lens_image(c, film, {0, 0});
            return Vector2d(
                (angle_at({0, centre.y}) + angle_at({w, centre.y})) * kDegreesPerRadian,
                (angle_at({centre.x, 0}) + angle_at({centre.x, h})) * kDegreesPerRadian);
          },
          [&](const LensSystemProjection& l) {
            // The angles between the chief rays of opposite edges' midpoints.
            auto focused = focused_lens_system(l.lens, lens_system_settings());
            LensSettings s = focused->settings();
            auto angle = [&](Point2d a, Point2d b) {
              auto ra = focused->chief_ray(a), rb = focused->chief_ray(b);
              if (!ra || !rb) return 0.0;
              return std::acos(std::clamp(dot(ra->direction, rb->direction), -1.0, 1.0)) *
                     kDegreesPerRadian;
            };
            double x = 0.5 * s.sensor_width_mm, y = 0.5 * s.sensor_height_mm;
            return Vector2d(angle({-x, 0}, {x, 0}), angle({0, -y}, {0, y}));
          },
      },
      projection);
}

double Camera::lens_radius_m() const {
  if (!lens.depth_of_field) return 0;
  return 0.5 * aperture_diameter_mm(lens, focal_length_mm()) * kMetresPerMillimetre;
}

double Camera::f_number() const {
  if (auto* l = std::get_if<LensSystemProjection>(&projection))
    return l->f_number.value_or(l->lens->f_number());
  double f = focal_length_mm();
  return f > 0 ? effective_f_number(lens, f) : lens.f_number;
}

double Camera::exposure_scale() const {
  return obscura::exposure_scale(exposure, f_number(), shutter.duration_s());
}

double Camera::readout_delay_s(Point2d film_point) const {
  if (shutter.line_time_s == 0) return 0;
  bool rows = reads_rows(shutter.readout);
  double lines = rows ? film.height_px : film.width_px;
  double line = std::clamp((rows ? film_point.y : film_point.x) - 0.5, 0.0, lines - 1);
  if (reads_backwards(shutter.readout)) line = lines - 1 - line;
  return line * shutter.line_time_s;
}

Shutter Camera::exposure_interval() const {
  Shutter s = shutter;
  bool rows = reads_rows(shutter.readout);
  s.close_s += (rows ? film.height_px - 1 : film.width_px - 1) * shutter.line_time_s;
  s.line_time_s = 0;
  return s;
}

double Camera::circle_of_confusion_px(double depth_m) const {
  return prepare().circle_of_confusion_px(depth_m);
}

std::optional<CameraRay> Camera::generate_ray(Point2d film_point, Point2d lens_sample,
                                              double time_s) const {
  return prepare().generate_ray(film_point, lens_sample, time_s);
}

PreparedCamera Camera::prepare(bool for_many_rays) const {
  return PreparedCamera(*this, for_many_rays);
}

PreparedCamera::PreparedCamera(const Camera& camera, bool for_many_rays) : camera_(&camera) {
  if (camera.has_projection_matrix()) {
    window_ = camera.screen_window();
    window_width_ = window_.x_max - window_.x_min;
    window_height_ = window_.y_max - window_.y_min;
  }
  width_px_ = camera.film.width_px;
  height_px_ = camera.film.height_px;
  lens_radius_m_ = camera.lens_radius_m();
  focal_length_mm_ = camera.focal_length_mm();
  film_width_mm_ = camera.film_size_mm().x;
  if (focal_length_mm_ > 0)
    aperture_radius_mm_ = 0.5 * aperture_diameter_mm(camera.lens, focal_length_mm_);
  if (camera.lens.vignetting.mechanical()) aperture_chords_ = aperture_chords(camera.lens.aperture);
  if (auto* c = std::get_if<CalibratedProjection>(&camera.projection)) {
    lens_map_.emplace(lens_map(*c));  // a copy of this thread's, not built again
    auto* pinhole = std::get_if<PinholeDistortion>(&c->lens);
    if (for_many_rays && pinhole && !(*pinhole == PinholeDistortion{})) {
      start_columns_ = int(std::ceil(width_px_ / kStartSpacing)) + 1;
      start_rows_ = int(std::ceil(height_px_ / kStartSpacing)) + 1;
      const double nan = std::numeric_limits<double>::quiet_NaN();
      starts_.reserve(size_t(start_columns_) * start_rows_);
      for (int j = 0; j < start_rows_; ++j)
        for (int i = 0; i < start_columns_; ++i) {
          Point2d raster(i * kStartSpacing, j * kStartSpacing);
          auto d = lens_map_->inverse(lens_image_from_raster(*c, camera.film, raster));
          starts_.push_back(d ? Point2d(d->x / d->z, d->y / d->z) : Point2d(nan, nan));
        }
    }
  }
  if (auto* l = std::get_if<LensSystemProjection>(&camera.projection)) {
    focused_lens_ = focused_lens_system(l->lens, camera.lens_system_settings());
    sensor_width_mm_ = focused_lens_->settings().sensor_width_mm;
    sensor_height_mm_ = focused_lens_->settings().sensor_height_mm;
    for (const LensSurface& surface : focused_lens_->lens().prescription().surfaces)
      if (surface.abbe_number > 0) disperses_ = true;
  }
  if (!camera.world_from_camera.is_animated())
    fixed_world_from_camera_ = &camera.world_from_camera.keys().front().transform;
}

// A lens-system camera's image coordinates (focused_lens_system.h): millimetres on the sensor
// from its centre, x right, y up.
Point2d PreparedCamera::image_mm_from_raster(Point2d raster) const {
  return {(raster.x / width_px_ - 0.5) * sensor_width_mm_,
          (0.5 - raster.y / height_px_) * sensor_height_mm_};
}

Point2d PreparedCamera::raster_from_image_mm(Point2d image) const {
  return {(image.x / sensor_width_mm_ + 0.5) * width_px_,
          (0.5 - image.y / sensor_height_mm_) * height_px_};
}

std::optional<Point2d> PreparedCamera::start_at(Point2d film_point) const {
  if (starts_.empty()) return std::nullopt;
  double gx = film_point.x / kStartSpacing, gy = film_point.y / kStartSpacing;
  // NaN-safe (math/safe_index.h): a NaN film point reads the first cell, not INT_MIN.
  int i = int(clamp_or_low(std::floor(gx), 0.0, double(start_columns_ - 2)));
  int j = int(clamp_or_low(std::floor(gy), 0.0, double(start_rows_ - 2)));
  double fx = gx - i, fy = gy - j;
  const Point2d* row0 = &starts_[size_t(j) * start_columns_ + i];
  const Point2d* row1 = row0 + start_columns_;
  Point2d a = row0[0], b = row0[1], c = row1[0], d = row1[1];
  Point2d p((a.x * (1 - fx) + b.x * fx) * (1 - fy) + (c.x * (1 - fx) + d.x * fx) * fy,
            (a.y * (1 - fx) + b.y * fx) * (1 - fy) + (c.y * (1 - fx) + d.y * fx) * fy);
  if (std::isnan(p.x) || std::isnan(p.y)) return std::nullopt;
  return p;
}

std::optional<CameraRay> PreparedCamera::generate_ray(Point2d film_point, Point2d lens_sample,
                                                      double time_s, double wavelength_nm) const {
  const Camera& camera = *camera_;
  const ThinLens& lens = camera.lens;
  // 1. The ray in camera space. `depth_per_t` turns the clipping range into t: perspective and
  //    orthographic rays clip at planes of constant depth along −Z, spherical ones by distance.
  struct LocalRay {
    Point3d origin;
    Vector3d direction;  // unit
    double depth_per_t;
    double weight = 1;
    double depth_at_origin = 0;  // a lens system's rays start in front of the camera's origin
  };
  auto pinhole_or_lens = [&](Point2d w) {
    Vector3d pinhole(w.x, w.y, -1);
    const Vignetting& vignetting = lens.vignetting;
    double natural = vignetting.natural ? natural_vignetting(w) : 1;
    if (!lens.depth_of_field)  // the barrel's share of the whole aperture, as a weight
      return LocalRay{{0, 0, 0}, normalize(pinhole), 0, natural * relative_barrel_share(w)};
    // Every lens point aims at the point of the focus plane that the pinhole ray reaches.
    Point3d focus = Point3d(0, 0, 0) + pinhole * lens.focus_distance_m;
    Point2d l = sample_aperture(lens.aperture, lens_sample);
    Point3d origin(lens_radius_m_ * l.x, lens_radius_m_ * l.y, 0);
    // The barrel keeps this lens point's ray or stops it: the cat-eye, sample by sample.
    bool kept = passes_barrel(vignetting, {aperture_radius_mm_ * l.x, aperture_radius_mm_ * l.y}, w,
                              lens.focus_distance_m * kMillimetresPerMetre);
    return LocalRay{origin, normalize(focus - origin), 0, kept ? natural : 0};
  };
  std::optional<LocalRay> local = std::visit(
      Overloaded{
          [&](const Perspective&) -> std::optional<LocalRay> {
            LocalRay r = pinhole_or_lens(window_from_raster(film_point));
            r.depth_per_t = -r.direction.z;
            return r;
          },
          [&](const Orthographic&) -> std::optional<LocalRay> {
            Point2d w = window_from_raster(film_point);
            return LocalRay{{w.x, w.y, 0}, {0, 0, -1}, 1};
          },
          [&](const Equirectangular&) -> std::optional<LocalRay> {
            Point2d uv(film_point.x / width_px_, film_point.y / height_px_);
            return LocalRay{{0, 0, 0}, equirectangular_direction(uv), 1};
          },
          [&](const Fisheye& f) -> std::optional<LocalRay> {
            auto d = fisheye_direction(f, fisheye_centered_from_raster(camera.film, film_point));
            if (!d) return std::nullopt;
            return LocalRay{{0, 0, 0}, *d, 1};
          },
          [&](const CalibratedProjection& c) -> std::optional<LocalRay> {
            Point2d image = lens_image_from_raster(c, camera.film, film_point);
            std::optional<Point2d> start = start_at(film_point);
            auto d = start ? lens_map_->inverse(image, *start) : lens_map_->inverse(image);
            if (!d) return std::nullopt;
            Vector3d direction = flip_yz(*d);
            return LocalRay{{0, 0, 0}, direction, is_planar(c.lens) ? -direction.z : 1};
          },
          [&](const LensSystemProjection&) -> std::optional<LocalRay> {
            auto r =
                focused_lens_->ray(image_mm_from_raster(film_point), lens_sample, wavelength_nm);
            if (!r || !(r->direction.z < 0)) return std::nullopt;  // stopped, or turned back
            return LocalRay{r->origin, r->direction, -r->direction.z, r->weight, -r->origin.z};
          },
      },
      camera.projection);
  if (!local) return std::nullopt;

  // 2. Into the world at this time; t keeps measuring world distance along the unit direction.
  auto into_world = [&](const Transform& world) {
    Vector3d world_direction = world(local->direction);
    double stretch = length(world_direction);
    CameraRay ray;
    ray.origin = world(local->origin);
    ray.direction = world_direction / stretch;
    ray.t_min =
        std::max(0.0, camera.near_m - local->depth_at_origin) / local->depth_per_t * stretch;
    ray.t_max = (camera.far_m - local->depth_at_origin) / local->depth_per_t * stretch;
    ray.time_s = time_s;
    ray.weight = local->weight;
    return ray;
  };
  if (fixed_world_from_camera_) return into_world(*fixed_world_from_camera_);
  return into_world(camera.world_from_camera.at(time_s));
}

// Camera::window_from_raster and raster_from_window with the window computed once (the same
// operations, so the same doubles).
Point2d PreparedCamera::window_from_raster(Point2d raster) const {
  return {window_.x_min + raster.x / width_px_ * window_width_,
          window_.y_max - raster.y / height_px_ * window_height_};
}

Point2d PreparedCamera::raster_from_window(Point2d p) const {
  return {(p.x - window_.x_min) / window_width_ * width_px_,
          (window_.y_max - p.y) / window_height_ * height_px_};
}

double PreparedCamera::relative_barrel_share(Point2d window) const {
  const ThinLens& lens = camera_->lens;
  return barrel_transmission(lens.vignetting, aperture_chords_, aperture_radius_mm_, window,
                             lens.focus_distance_m * kMillimetresPerMetre);
}

double PreparedCamera::relative_illumination(Point2d film_point) const {
  const Vignetting& v = camera_->lens.vignetting;
  if (!v.any() || !std::holds_alternative<Perspective>(camera_->projection)) return 1;
  Point2d w = window_from_raster(film_point);
  return (v.natural ? natural_vignetting(w) : 1) * relative_barrel_share(w);
}

double Camera::relative_illumination(Point2d film_point) const {
  return prepare().relative_illumination(film_point);
}

double PreparedCamera::circle_of_confusion_px(double depth_m) const {
  if (!camera_->lens.depth_of_field) return 0;
  double c_mm = circle_of_confusion_mm(camera_->lens, focal_length_mm_, depth_m);
  return c_mm / film_width_mm_ * width_px_;
}

Transform PreparedCamera::world_from_camera(double time_s) const {
  return fixed_world_from_camera_ ? *fixed_world_from_camera_
                                  : camera_->world_from_camera.at(time_s);
}

std::optional<FilmProjection> Camera::project(Point3d world, double time_s) const {
  return prepare().project(world, time_s);
}

std::optional<Point3d> Camera::unproject(Point2d film_point, double depth_m, double time_s) const {
  return prepare().unproject(film_point, depth_m, time_s);
}

std::optional<FilmProjection> PreparedCamera::project(Point3d world, double time_s) const {
  const Camera& camera = *camera_;
  const FilmGeometry& film = camera.film;
  const Projection& projection = camera.projection;
  const double near_m = camera.near_m, far_m = camera.far_m;
  Point3d q = inverse(world_from_camera(time_s))(world);
  Vector3d d = to_vector(q);
  // Depth along −Z for the planar projections, distance for the spherical ones; then the film
  // point, or nothing outside a fisheye's circle.
  bool planar = planar_depth(projection);
  double depth = planar ? -q.z : length(d);
  if (!(depth >= near_m && depth <= far_m) || (!planar && depth == 0)) return std::nullopt;
  std::optional<Point2d> film_point =
      std::visit(Overloaded{
                     [&](const Perspective&) -> std::optional<Point2d> {
                       return raster_from_window({q.x / depth, q.y / depth});
                     },
                     [&](const Orthographic&) -> std::optional<Point2d> {
                       return raster_from_window({q.x, q.y});
                     },
                     [&](const Equirectangular&) -> std::optional<Point2d> {
                       Point2d uv = equirectangular_uv(d);
                       return Point2d(uv.x * film.width_px, uv.y * film.height_px);
                     },
                     [&](const Fisheye& f) -> std::optional<Point2d> {
                       auto c = fisheye_centered(f, d);
                       if (!c) return std::nullopt;
                       return raster_from_fisheye_centered(film, *c);
                     },
                     [&](const CalibratedProjection& c) -> std::optional<Point2d> {
                       auto image = lens_map_->forward(flip_yz(d));
                       if (!image) return std::nullopt;
                       return raster_from_lens_image(c, film, *image);
                     },
                     [&](const LensSystemProjection&) -> std::optional<Point2d> {
                       auto image = focused_lens_->image_point_of(q);
                       if (!image) return std::nullopt;
                       return raster_from_image_mm(*image);
                     },
                 },
                 projection);
  if (!film_point || !on_film(film, *film_point)) return std::nullopt;
  return FilmProjection{*film_point, depth};
}

std::optional<Point3d> PreparedCamera::unproject(Point2d film_point, double depth_m,
                                                 double time_s) const {
  const FilmGeometry& film = camera_->film;
  std::optional<Point3d> q = std::visit(
      Overloaded{
          [&](const Perspective&) -> std::optional<Point3d> {
            Point2d w = window_from_raster(film_point);
            return Point3d(w.x * depth_m, w.y * depth_m, -depth_m);
          },
          [&](const Orthographic&) -> std::optional<Point3d> {
            Point2d w = window_from_raster(film_point);
            return Point3d(w.x, w.y, -depth_m);
          },
          [&](const Equirectangular&) -> std::optional<Point3d> {
            Point2d uv(film_point.x / film.width_px, film_point.y / film.height_px);
            return Point3d(0, 0, 0) + equirectangular_direction(uv) * depth_m;
          },
          [&](const Fisheye& f) -> std::optional<Point3d> {
            auto d = fisheye_direction(f, fisheye_centered_from_raster(film, film_point));
            if (!d) return std::nullopt;
            return Point3d(0, 0, 0) + *d * depth_m;
          },
          [&](const CalibratedProjection& c) -> std::optional<Point3d> {
            auto d = lens_map_->inverse(lens_image_from_raster(c, film, film_point));
            if (!d) return std::nullopt;
            Vector3d direction = flip_yz(*d);
            double scale = is_planar(c.lens) ? depth_m / -direction.z : depth_m;
            return Point3d(0, 0, 0) + direction * scale;
          },
          [&](const LensSystemProjection&) -> std::optional<Point3d> {
            // Along the chief ray to the plane at depth_m in front of the sensor.
            auto chief = focused_lens_->chief_ray(image_mm_from_raster(film_point));
            if (!chief || !(chief->direction.z < 0)) return std::nullopt;
            return chief->origin +
                   chief->direction * ((chief->origin.z + depth_m) / -chief->direction.z);
          },
      },
      camera_->projection);
  if (!q) return std::nullopt;
  return world_from_camera(time_s)(*q);
}

Matrix4 Camera::view_matrix(double time_s) const {
  return world_from_camera.at(time_s).inverse_matrix();
}

bool Camera::has_projection_matrix() const {
  return std::holds_alternative<Perspective>(projection) ||
         std::holds_alternative<Orthographic>(projection);
}

Matrix4 Camera::projection_matrix() const {
  if (!has_projection_matrix())
    throw Error("camera.projection_matrix", "a " + std::string(projection_name(projection)) +
                                                " camera has no projection matrix");
  ScreenWindow w = screen_window();
  double sx = 2 / (w.x_max - w.x_min), sy = 2 / (w.y_max - w.y_min);
  double ox = (w.x_max + w.x_min) / (w.x_max - w.x_min);
  double oy = (w.y_max + w.y_min) / (w.y_max - w.y_min);
  double n = near_m, f = far_m;
  if (std::holds_alternative<Orthographic>(projection)) {  // glOrtho
    // A far plane at infinity is glOrtho's limit, every depth at the near plane: a renderer
    // that keeps depth fits a finite far plane to its scene (raster/depth_range.h).
    const double a = std::isinf(f) ? 0 : -2 / (f - n), b = std::isinf(f) ? -1 : -(f + n) / (f - n);
    return Matrix4::from_rows({{{sx, 0, 0, -ox}, {0, sy, 0, -oy}, {0, 0, a, b}, {0, 0, 0, 1}}});
  }
  // glFrustum with (left, right, bottom, top) = near × the window on z = −1.
  double a = std::isinf(f) ? -1 : -(f + n) / (f - n);
  double b = std::isinf(f) ? -2 * n : -2 * f * n / (f - n);
  return Matrix4::from_rows({{{sx, 0, ox, 0}, {0, sy, oy, 0}, {0, 0, a, b}, {0, 0, -1, 0}}});
}

Matrix4 Camera::raster_from_ndc() const {
  double w = film.width_px, h = film.height_px;
  return Matrix4::from_rows(
      {{{0.5 * w, 0, 0, 0.5 * w}, {0, -0.5 * h, 0, 0.5 * h}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
}

}  // namespace obscura

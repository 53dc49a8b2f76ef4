#include "obscura/raster/lens_warp.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "obscura/camera/intrinsics.h"
#include "obscura/film/work_share.h"
#include "obscura/math/error.h"
#include "obscura/math/safe_index.h"
#include "obscura/raster/render_target.h"

namespace obscura::raster {

namespace {

constexpr double kPi = std::numbers::pi;
// One fitted view while every ray is within this angle of the axis: beyond it a single pinhole
// view spends most of its pixels on the field's edges (its density grows as 1/cos²).
const double kSingleViewMaxAngle = 60 * kPi / 180;

// The camera's rays in its own frame (X right, Y up, looking down −Z): the camera at the origin,
// through the lens centre.
Camera local_camera(const Camera& camera) {
  Camera local = camera;
  local.world_from_camera = AnimatedTransform(Transform());
  local.lens.depth_of_field = false;
  return local;
}

// The six cube faces: each view's turn, looking down its face's axis. Order: −Z (ahead), +X, −X,
// +Y, −Y, +Z (behind).
const std::array<Transform, 6>& cube_turns() {
  static const std::array<Transform, 6> turns = {
      Transform(),
      Transform::rotate_y(-kPi / 2),
      Transform::rotate_y(kPi / 2),
      Transform::rotate_x(kPi / 2),
      Transform::rotate_x(-kPi / 2),
      Transform::rotate_y(kPi),
  };
  return turns;
}

int cube_face(Vector3f d) {
  float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  if (az >= ax && az >= ay) return d.z <= 0 ? 0 : 5;
  if (ax >= ay) return d.x > 0 ? 1 : 2;
  return d.y > 0 ? 3 : 4;
}

// A perspective camera at `camera`'s position, turned by `camera_from_view`, whose screen window
// is `window` on a width × height film.
Camera pinhole_view(const Camera& camera, const Transform& camera_from_view, ScreenWindow window,
                    int width, int height) {
  Intrinsics k;
  k.fx = width / (window.x_max - window.x_min);
  k.fy = height / (window.y_max - window.y_min);
  k.cx = -window.x_min * k.fx - 0.5;
  k.cy = window.y_max * k.fy - 0.5;
  Camera view = camera_from_intrinsics(k, width, height);
  view.name = camera.name;
  view.near_m = camera.near_m;
  view.far_m = camera.far_m;
  view.shutter = camera.shutter;
  view.exposure = camera.exposure;
  view.lens = camera.lens;
  view.lens.depth_of_field = false;
  std::vector<AnimatedTransform::Key> keys;
  for (const AnimatedTransform::Key& key : camera.world_from_camera.keys())
    keys.push_back({key.time_s, key.transform * camera_from_view});
  view.world_from_camera = AnimatedTransform(std::move(keys));
  view.validate();
  return view;
}

// The directions through the crop's pixel corners, in the camera's frame; NaN where a corner sees
// nothing. (W + 1) × (H + 1), row by row.
struct CornerRays {
  int columns = 0, rows = 0;
  std::vector<Vector3f> rays;
  const Vector3f& at(int i, int j) const { return rays[size_t(j) * columns + i]; }
};

CornerRays corner_rays(const Camera& local) {
  Bounds2i crop = local.film.crop_pixels();
  CornerRays c;
  c.columns = crop.width() + 1;
  c.rows = crop.height() + 1;
  c.rays.resize(size_t(c.columns) * c.rows);
  PreparedCamera prepared = local.prepare();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  tbb::parallel_for(0, c.rows, [&](int j) {
    for (int i = 0; i < c.columns; ++i) {
      auto ray = prepared.generate_ray({double(crop.min.x + i), double(crop.min.y + j)});
      c.rays[size_t(j) * c.columns + i] = ray ? Vector3f(ray->direction) : Vector3f(nan, nan, nan);
    }
  });
  return c;
}

bool sees(const Vector3f& d) {
  return !std::isnan(d.x);
}

double angle_between(const Vector3f& a, const Vector3f& b) {
  Vector3d x(a), y(b);
  return std::atan2(length(cross(x, y)), dot(x, y));
}

// What one view needs for lookups: its turn back into the view's frame, its window and size, its
// rendered images.
struct RenderedView {
  Transform view_from_camera;
  ScreenWindow window;
  int width = 0, height = 0;
  Image color;
  std::optional<Image> normal, depth, id;  // depth along the view's axis

  // The view's raster point for direction `d` (camera frame); nothing behind the view.
  std::optional<Point2d> raster_of(Vector3d d) const {
    Vector3d l = view_from_camera(d);
    if (!(l.z < 0)) return std::nullopt;
    double tx = l.x / -l.z, ty = l.y / -l.z;
    return Point2d((tx - window.x_min) / (window.x_max - window.x_min) * width,
                   (window.y_max - ty) / (window.y_max - window.y_min) * height);
  }
  // The point (camera frame) the view's pixel (x, y) sees at its centre, `view_depth` deep.
  Point3d point_at(int x, int y, double view_depth) const {
    double tx = window.x_min + (x + 0.5) / width * (window.x_max - window.x_min);
    double ty = window.y_max - (y + 0.5) / height * (window.y_max - window.y_min);
    return inverse(view_from_camera)(Point3d(tx * view_depth, ty * view_depth, -view_depth));
  }
};

// Bilinear lookup at raster point p (pixel centres at half-integers), clamped to the image.
Rgb bilinear(const Image& image, Point2d p) {
  // NaN-safe (math/safe_index.h): std::clamp passes NaN on to int().
  double x = clamp_or_low(p.x - 0.5, 0.0, double(image.width - 1));
  double y = clamp_or_low(p.y - 0.5, 0.0, double(image.height - 1));
  int x0 = int(x), y0 = int(y);  // x, y ≥ 0: truncation is floor
  int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  float fx = float(x - x0), fy = float(y - y0);
  Rgb top = image.rgb(x0, y0) * (1 - fx) + image.rgb(x1, y0) * fx;
  Rgb bottom = image.rgb(x0, y1) * (1 - fx) + image.rgb(x1, y1) * fx;
  return top * (1 - fy) + bottom * fy;
}

}  // namespace

LensViews plan_lens_views(const Camera& camera, const LensWarpSettings& settings) {
  if (settings.oversampling < 1 || settings.subpixels < 1 || settings.max_view_side_px < 16)
    throw Error("lens_warp.settings", "oversampling and subpixels must be ≥ 1, views ≥ 16 px");
  Camera local = local_camera(camera);
  CornerRays corners = corner_rays(local);

  // The field: the widest angle from the axis, the finest angular and tangent-plane steps
  // between neighbouring corners, the tangent-plane bounds and the cube faces looked into.
  double widest = 0, finest_angle = std::numeric_limits<double>::infinity();
  double finest_tangent = finest_angle;
  ScreenWindow bounds{finest_angle, -finest_angle, finest_angle, -finest_angle};
  std::array<bool, 6> faces{};
  bool any = false;
  for (int j = 0; j < corners.rows; ++j)
    for (int i = 0; i < corners.columns; ++i) {
      const Vector3f& d = corners.at(i, j);
      if (!sees(d)) continue;
      any = true;
      widest = std::max(widest, std::acos(std::clamp(double(-d.z), -1.0, 1.0)));
      faces[size_t(cube_face(d))] = true;
      double tx = d.z < 0 ? d.x / -d.z : 0, ty = d.z < 0 ? d.y / -d.z : 0;
      bounds = {std::min(bounds.x_min, tx), std::max(bounds.x_max, tx), std::min(bounds.y_min, ty),
                std::max(bounds.y_max, ty)};
      for (auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (i + di >= corners.columns || j + dj >= corners.rows) continue;
        const Vector3f& e = corners.at(i + di, j + dj);
        if (!sees(e)) continue;
        finest_angle = std::min(finest_angle, angle_between(d, e));
        if (d.z < 0 && e.z < 0)
          finest_tangent = std::min(finest_tangent, std::hypot(e.x / -e.z - tx, e.y / -e.z - ty));
      }
    }
  if (!any)
    throw Error("camera",
                "no pixel of the image sees through the lens (every ray is outside its "
                "field)");
  if (!(finest_angle > 0 && std::isfinite(finest_angle))) finest_angle = 1e-3;
  if (!(finest_tangent > 0 && std::isfinite(finest_tangent))) finest_tangent = finest_angle;

  LensViews plan;
  const int cap = settings.max_view_side_px;
  auto capped = [&](double side, const char* what) {
    if (side <= cap) return int(std::ceil(side));
    plan.warnings.push_back(std::string("lens views: the ") + what + " needs " +
                            std::to_string(int(std::ceil(side))) + " px per side; capped at " +
                            std::to_string(cap) + " (fine detail is softer than the tracer's)");
    return cap;
  };
  if (widest <= kSingleViewMaxAngle) {
    double pixel = finest_tangent / settings.oversampling;
    double margin_x = 0.01 * (bounds.x_max - bounds.x_min) + 2 * pixel;
    double margin_y = 0.01 * (bounds.y_max - bounds.y_min) + 2 * pixel;
    ScreenWindow w{bounds.x_min - margin_x, bounds.x_max + margin_x, bounds.y_min - margin_y,
                   bounds.y_max + margin_y};
    int width = capped((w.x_max - w.x_min) / pixel, "fitted view");
    int height = capped((w.y_max - w.y_min) / pixel, "fitted view");
    plan.views.push_back(pinhole_view(camera, Transform(), w, width, height));
    plan.camera_from_view.push_back(Transform());
    return plan;
  }
  // Cube faces: the finest angular step is the tangent step at a face's centre, where a face's
  // pixels are widest in angle; two pixels of margin keep bilinear lookups at the seams inside.
  plan.cube = true;
  double pixel = finest_angle / settings.oversampling;
  int side = capped(2 / pixel + 4, "cube face");
  double half = 1 + 2.0 / std::max(1, side - 4) * 2;
  for (size_t f = 0; f < 6; ++f) {
    if (!faces[f]) continue;
    plan.views.push_back(
        pinhole_view(camera, cube_turns()[f], {-half, half, -half, half}, side, side));
    plan.camera_from_view.push_back(cube_turns()[f]);
  }
  return plan;
}

LensRender render_through_lens(const SceneRasterizer& rasterizer, const Camera& camera,
                               const LensWarpSettings& settings, Film& film) {
  camera.validate();
  LensViews plan = plan_lens_views(camera, settings);
  LensRender result;
  result.warnings = plan.warnings;
  const bool aovs = rasterizer.settings().aovs;
  const double camera_exposure = camera.exposure_scale();

  std::vector<RenderedView> views(plan.views.size());
  for (size_t v = 0; v < plan.views.size(); ++v) {
    const Camera& view = plan.views[v];
    RenderedView& r = views[v];
    r.view_from_camera = inverse(plan.camera_from_view[v]);
    r.window = view.screen_window();
    r.width = view.film.width_px;
    r.height = view.film.height_px;
    Film view_film(r.width, r.height);
    RenderTarget target = rasterizer.make_target(view);
    rasterizer.render(view, view_film, &target);
    r.color = view_film.to_image();
    // A view's f-number follows its focal length when the aperture is given in millimetres: keep
    // the camera's exposure.
    float rescale = float(camera_exposure / view.exposure_scale());
    if (rescale != 1)
      for (float& value : r.color.data) value *= rescale;
    if (aovs) {
      r.normal = normal_image(target);
      r.depth = depth_image(target);
      r.id = id_image(target);
    }
  }
  // Which view a direction is looked up in: the fitted one, or its cube face's.
  std::array<int, 6> view_of_face{};
  view_of_face.fill(-1);
  if (plan.cube)
    for (size_t v = 0; v < plan.views.size(); ++v)
      for (size_t f = 0; f < 6; ++f)
        if (plan.camera_from_view[v] == cube_turns()[f]) view_of_face[f] = int(v);
  auto locate = [&](Vector3d d) -> std::optional<std::pair<const RenderedView*, Point2d>> {
    int v = plan.cube ? view_of_face[size_t(cube_face(Vector3f(d)))] : 0;
    if (v < 0) return std::nullopt;
    auto p = views[size_t(v)].raster_of(d);
    if (!p) return std::nullopt;
    return std::pair{&views[size_t(v)], *p};
  };

  Camera local = local_camera(camera);
  PreparedCamera prepared = local.prepare(/*for_many_rays=*/true);
  Bounds2i crop = camera.film.crop_pixels();
  const int width = crop.width(), height = crop.height();
  if (film.width() != width || film.height() != height)
    throw Error("render_through_lens", "the film must have the crop's size");
  TileDeal deal{.width = width, .height = height, .tile_size = kTileSize, .parts = settings.parts};
  if (aovs) {
    result.normal.emplace(width, height, 3);
    result.normal->channel_names = {"X", "Y", "Z"};
    result.depth.emplace(width, height, 1);
    result.depth->channel_names = {"Z"};
    result.range.emplace(width, height, 1);
    result.range->channel_names = {"range"};
    result.id.emplace(width, height, 1);
    result.id->channel_names = {"id"};
  }
  const int s = settings.subpixels;
  const float weight = 1.f / float(s * s);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      if (deal.owner(x, y) != settings.part) continue;
      Rgb sum;
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          Point2d film_point(crop.min.x + x + (i + 0.5) / s, crop.min.y + y + (j + 0.5) / s);
          auto ray = prepared.generate_ray(film_point);
          if (!ray) continue;
          auto at = locate(ray->direction);
          if (at) sum += bilinear(at->first->color, at->second) * weight;
        }
      film.add_sample({x, y}, sum, 1.f);
      if (!aovs) continue;
      // The AOVs: the nearest view pixel along the pixel centre's ray.
      float inf = std::numeric_limits<float>::infinity();
      result.depth->at(x, y, 0) = inf;
      result.range->at(x, y, 0) = inf;
      result.id->at(x, y, 0) = -1;
      auto ray = prepared.generate_ray({crop.min.x + x + 0.5, crop.min.y + y + 0.5});
      auto at = ray ? locate(ray->direction) : std::nullopt;
      if (!at) continue;
      const RenderedView& v = *at->first;
      int vx = std::clamp(int(at->second.x), 0, v.width - 1);
      int vy = std::clamp(int(at->second.y), 0, v.height - 1);
      for (int c = 0; c < 3; ++c) result.normal->at(x, y, c) = v.normal->at(vx, vy, c);
      const float view_depth = v.depth->at(vx, vy, 0);
      if (std::isfinite(view_depth)) {
        const Point3d seen = v.point_at(vx, vy, view_depth);
        const double depth = -seen.z;
        // The range of the point of the pixel centre's ray at that depth (exact on surfaces facing
        // the camera); rays nearly across the axis, where depth tells little, take the seen
        // point's projection onto the ray.
        const double along = -ray->direction.z;
        const double range = std::abs(along) > 0.05 ? (depth + ray->origin.z) / along
                                                    : dot(seen - ray->origin, ray->direction);
        result.depth->at(x, y, 0) = float(depth);
        result.range->at(x, y, 0) = float(range);
      }
      result.id->at(x, y, 0) = v.id->at(vx, vy, 0);
    }
  });
  return result;
}

}  // namespace obscura::raster

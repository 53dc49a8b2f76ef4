#include "obscura/raster/ground_truth_render.h"

#include <cmath>

#include "obscura/math/error.h"

namespace obscura::raster {

namespace {

// What the pixel centre sees at one time, from the rasterizer's ids and the scene's triangle.
struct Seen {
  Point3d position;
  Vector3d shading_normal, geometric_normal;
  uint32_t instance = 0, triangle = 0;
  double range_m = 0;
};

Vector3d to_double(Vector3f v) {
  return {v.x, v.y, v.z};
}

std::optional<Seen> seen_at(const RenderTarget& target, const SurfaceMotion& motion,
                            const PreparedCamera& camera, int x, int y, Point2d film_point,
                            double time_s) {
  const uint32_t object = target.object_id_at(x, y);
  if (object == kNoObject) return std::nullopt;
  std::optional<CameraRay> ray = camera.generate_ray(film_point, {0.5, 0.5}, time_s);
  if (!ray) return std::nullopt;
  Seen s;
  s.instance = object - 1;
  s.triangle = target.primitive_id_at(x, y);
  const Vector3f drawn_normal = target.normals()[target.sample_index(x, y)];
  s.shading_normal = length(drawn_normal) > 0 ? normalize(to_double(drawn_normal)) : Vector3d();
  const Scene& scene = motion.scene();
  const Instance& instance = scene.instances[s.instance];
  const bool blended = scene.materials[scene.material_of(instance)].alpha_mode == AlphaMode::kBlend;
  const double drawn_depth = target.view_depth_at(x, y);

  bool exact = false;
  if (!blended) {
    const std::array<Point3d, 3> tri = motion.world_triangle(s.instance, s.triangle, time_s);
    const Vector3d n = motion.geometric_normal(s.instance, s.triangle, time_s);
    const double along = dot(ray->direction, n);
    if (std::abs(along) > 1e-12 && length(n) > 0) {
      const double t = dot(tri[0] - ray->origin, n) / along;
      const Point3d p = ray->origin + ray->direction * t;
      const double depth = optical_axis_depth(camera, p, time_s);
      // The drawn depth is interpolated in float: a plane that agrees with it is the one drawn.
      if (t > 0 && std::abs(depth - drawn_depth) <= 1e-3 * std::abs(drawn_depth)) {
        s.position = p;
        s.geometric_normal = n;
        exact = true;
      }
    }
  }
  if (!exact) {
    std::optional<Point3d> p = camera.unproject(film_point, drawn_depth, time_s);
    if (!p) return std::nullopt;
    s.position = *p;
    s.geometric_normal = s.shading_normal;
  }
  // The drawn normal faces the camera; the ground truth's keeps the winding's side, as Ng.
  if (dot(s.shading_normal, s.geometric_normal) < 0) s.shading_normal = -s.shading_normal;
  s.range_m = length(s.position - ray->origin);
  return s;
}

RenderTarget draw_at(const SceneRasterizer& rasterizer, const Camera& camera, double time_s) {
  RenderTarget target = rasterizer.make_target(camera);
  RasterFrame frame;
  frame.time_s = time_s;  // the camera's own matrices at that time
  rasterizer.render_frame(camera, frame, target);
  return target;
}

}  // namespace

void check_ground_truth_camera(const Camera& camera) {
  // Exact per-pixel values need the pixel's own time and a matrix: the tracer has both for every
  // camera.
  if (!camera.has_projection_matrix() || camera.shutter.line_time_s > 0)
    throw Error("raster ground truth",
                std::string("the rasterizer's ground truth is exact for perspective and "
                            "orthographic cameras with a global shutter; this camera is ") +
                    std::string(projection_name(camera.projection)) +
                    (camera.shutter.line_time_s > 0 ? " with a rolling shutter" : "") +
                    ": use the tracer (--renderer path)");
}

GroundTruthBuffer render_ground_truth(const SceneRasterizer& rasterizer,
                                      const SurfaceMotion& motion, const Camera& camera,
                                      const GroundTruthTimes& times,
                                      const std::atomic<bool>* cancel) {
  auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  if (!rasterizer.settings().aovs || rasterizer.settings().msaa_samples != 1)
    throw Error("raster ground truth",
                "needs a rasterizer with aovs on and one sample per pixel (no MSAA)");
  check_ground_truth_camera(camera);
  const Bounds2i crop = camera.film.crop_pixels();
  const double t0 = times.first_s, t1 = times.second_s;
  GroundTruthBuffer buffer(crop.width(), crop.height());
  if (cancelled()) return buffer;
  const RenderTarget first = draw_at(rasterizer, camera, t0);
  if (cancelled()) return buffer;
  const RenderTarget second = draw_at(rasterizer, camera, t1);
  const PreparedCamera prepared = camera.prepare();
  const Scene& scene = motion.scene();
  for (int y = 0; y < crop.height() && !cancelled(); ++y)
    for (int x = 0; x < crop.width(); ++x) {
      const Point2d film_point(crop.min.x + x + 0.5, crop.min.y + y + 0.5);
      buffer.set_time(x, y, t0);
      if (std::optional<Seen> s = seen_at(first, motion, prepared, x, y, film_point, t0)) {
        buffer.set_surface(x, y,
                           {.z_m = optical_axis_depth(prepared, s->position, t0),
                            .range_m = s->range_m,
                            .position = s->position,
                            .shading_normal = s->shading_normal,
                            .geometric_normal = s->geometric_normal,
                            .instance = int(s->instance),
                            .material = int(scene.material_of(scene.instances[s->instance]))});
        auto at = [&](double t) {
          return motion.follow(s->instance, s->triangle, s->position, t0, t);
        };
        buffer.set_forward_flow(x, y, optical_flow(prepared, film_point, at, t1));
      }
      if (std::optional<Seen> s = seen_at(second, motion, prepared, x, y, film_point, t1)) {
        auto at = [&](double t) {
          return motion.follow(s->instance, s->triangle, s->position, t1, t);
        };
        buffer.set_backward_flow(x, y, optical_flow(prepared, film_point, at, t0));
      }
    }
  return buffer;
}

}  // namespace obscura::raster

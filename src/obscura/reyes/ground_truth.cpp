#include "obscura/reyes/ground_truth.h"

#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "obscura/film/film.h"
#include "obscura/math/error.h"
#include "obscura/reyes/render.h"

namespace obscura::reyes {

namespace {

struct Surface {
  Point3d position;
  Vector3d shading_normal, geometric_normal;
  double range_m = 0;
};

// An analytic sphere's surface where `ray` first meets it (from outside, else from inside).
std::optional<Surface> sphere_surface_at(const SurfaceMotion& motion, uint32_t instance,
                                         const CameraRay& ray, double time_s) {
  const Scene& scene = motion.scene();
  const AnalyticSphere& sphere = *scene.meshes[scene.instances[instance].mesh].analytic_sphere;
  const Transform world_from_object = motion.world_from_object(instance, time_s);
  const Transform object_from_world = inverse(world_from_object);
  // In object space, where the sphere is round; t is the same along the mapped ray.
  const Point3d o = object_from_world(ray.origin);
  const Vector3d d = object_from_world(ray.direction);
  const Vector3d oc = o - Point3d(sphere.center.x, sphere.center.y, sphere.center.z);
  const double a = dot(d, d), b = dot(oc, d), r = sphere.radius;
  const double discriminant = b * b - a * (dot(oc, oc) - r * r);
  if (!(discriminant >= 0 && a > 0)) return std::nullopt;
  const double root = std::sqrt(discriminant);
  double t = (-b - root) / a;
  if (!(t > 0)) t = (-b + root) / a;
  if (!(t > 0)) return std::nullopt;
  const Vector3d n_object = (oc + d * t) / r;
  const Normal3d nw = world_from_object(Normal3d(n_object.x, n_object.y, n_object.z));
  Surface s;
  s.position = ray.origin + ray.direction * t;
  s.geometric_normal = Vector3d(nw.x, nw.y, nw.z) / length(Vector3d(nw.x, nw.y, nw.z));
  s.shading_normal = s.geometric_normal;
  s.range_m = t;
  return s;
}

// The triangle's surface where the pixel centre's ray (lens centre, at `time_s`) meets its plane
// (an analytic surface's where the ray meets it).
std::optional<Surface> surface_at(const SurfaceMotion& motion, const PreparedCamera& camera,
                                  SeenTriangle seen, Point2d film_point, double time_s) {
  const std::optional<CameraRay> ray = camera.generate_ray(film_point, {0.5, 0.5}, time_s);
  if (!ray) return std::nullopt;
  const uint32_t instance = uint32_t(seen.instance);
  if (seen.triangle == kAnalyticSurface) return sphere_surface_at(motion, instance, *ray, time_s);
  const std::array<Point3d, 3> tri = motion.world_triangle(instance, seen.triangle, time_s);
  const Vector3d n = motion.geometric_normal(instance, seen.triangle, time_s);
  const double facing = dot(ray->direction, n);
  if (!(std::abs(facing) > 1e-12)) return std::nullopt;
  const double t = dot(tri[0] - ray->origin, n) / facing;
  if (!(t > 0)) return std::nullopt;
  Surface s;
  s.position = ray->origin + ray->direction * t;
  s.geometric_normal = n;
  s.range_m = t;
  s.shading_normal = n;
  const Scene& scene = motion.scene();
  const Mesh& mesh = scene.meshes[scene.instances[instance].mesh];
  if (!mesh.normals.empty()) {
    const std::array<double, 3> b = barycentric(tri, s.position);
    Vector3d sum;
    for (int k = 0; k < 3; ++k) {
      const Normal3f o = mesh.normals[mesh.indices[3 * size_t(seen.triangle) + size_t(k)]];
      sum += Vector3d(o.x, o.y, o.z) * b[size_t(k)];
    }
    const Normal3d w = motion.world_from_object(instance, time_s)(Normal3d(sum));
    const Vector3d wv(w.x, w.y, w.z);
    if (length(wv) > 0) s.shading_normal = wv / length(wv);
    // The ground truth keeps the winding's side, as the geometric normal does.
    if (dot(s.shading_normal, n) < 0) s.shading_normal = -s.shading_normal;
  }
  return s;
}

// What REYES's hider sees at every pixel centre at `time_s`.
std::vector<SeenTriangle> seen_at(const ReyesScene& scene, const Camera& camera,
                                  const ReyesSettings& settings, double time_s) {
  Camera still = camera;
  still.shutter.open_s = still.shutter.close_s = time_s;
  still.lens.depth_of_field = false;
  still.film.filter = BoxFilter{1e-6};
  ReyesSettings one = settings;
  one.pixel_samples = 1;
  const Bounds2i crop = camera.film.crop_pixels();
  Film film(crop.width(), crop.height());
  std::vector<SeenTriangle> seen;
  render(scene, still, one, film, nullptr, {}, &seen);
  return seen;
}

}  // namespace

void check_ground_truth_camera(const Camera& camera) {
  const bool planar = std::holds_alternative<Perspective>(camera.projection) ||
                      std::holds_alternative<Orthographic>(camera.projection);
  if (!planar || camera.shutter.line_time_s > 0)
    throw Error("reyes ground truth",
                "REYES's ground truth is exact for perspective and orthographic cameras with a "
                "global shutter: use the tracer (--renderer path)");
}

GroundTruthBuffer render_ground_truth(const ReyesScene& scene, const Camera& camera,
                                      const ReyesSettings& settings, const GroundTruthTimes& times,
                                      const std::atomic<bool>* cancel) {
  auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  check_ground_truth_camera(camera);
  const Bounds2i crop = camera.film.crop_pixels();
  const double t0 = times.first_s, t1 = times.second_s;
  GroundTruthBuffer buffer(crop.width(), crop.height());
  if (cancelled()) return buffer;
  const std::vector<SeenTriangle> first = seen_at(scene, camera, settings, t0);
  if (cancelled()) return buffer;
  const std::vector<SeenTriangle> second = seen_at(scene, camera, settings, t1);
  const PreparedCamera prepared = camera.prepare();
  const SurfaceMotion& motion = scene.motion();
  const Scene& s = scene.scene();
  for (int y = 0; y < crop.height() && !cancelled(); ++y)
    for (int x = 0; x < crop.width(); ++x) {
      const size_t i = size_t(y) * size_t(crop.width()) + size_t(x);
      const Point2d film_point(crop.min.x + x + 0.5, crop.min.y + y + 0.5);
      buffer.set_time(x, y, t0);
      if (first[i].instance >= 0)
        if (std::optional<Surface> f = surface_at(motion, prepared, first[i], film_point, t0)) {
          const uint32_t instance = uint32_t(first[i].instance);
          buffer.set_surface(x, y,
                             {.z_m = optical_axis_depth(prepared, f->position, t0),
                              .range_m = f->range_m,
                              .position = f->position,
                              .shading_normal = f->shading_normal,
                              .geometric_normal = f->geometric_normal,
                              .instance = int(instance),
                              .material = int(s.material_of(s.instances[instance]))});
          auto at = [&](double t) {
            return motion.follow(instance, first[i].triangle, f->position, t0, t);
          };
          buffer.set_forward_flow(x, y, optical_flow(prepared, film_point, at, t1));
        }
      if (second[i].instance >= 0)
        if (std::optional<Surface> b = surface_at(motion, prepared, second[i], film_point, t1)) {
          auto at = [&](double t) {
            return motion.follow(uint32_t(second[i].instance), second[i].triangle, b->position, t1,
                                 t);
          };
          buffer.set_backward_flow(x, y, optical_flow(prepared, film_point, at, t0));
        }
    }
  return buffer;
}

}  // namespace obscura::reyes

#include "obscura/trace/ground_truth_render.h"

#include <cmath>
#include <string>

#include "obscura/film/tiles.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr int kTileSize = 16;

struct CentreHit {
  CameraRay ray;
  SurfaceHit hit;
  Point3d position;  // in double precision, along the double-precision ray
};

std::optional<CentreHit> centre_hit(const TraceScene& scene, const PreparedCamera& camera,
                                    Point2d film_point, double time_s) {
  std::optional<CameraRay> ray = camera.generate_ray(film_point, {0.5, 0.5}, time_s);
  if (!ray) return std::nullopt;
  std::optional<SurfaceHit> hit = scene.intersect(ray->to_ray());
  if (!hit) return std::nullopt;
  return CentreHit{*ray, *hit, ray->origin + ray->direction * double(hit->t)};
}

Vector3d to_double(Normal3f n) {
  return {n.x, n.y, n.z};
}

void check_time(const Shutter& compiled, double time_s, const char* which) {
  if (!(time_s >= compiled.open_s && time_s <= compiled.close_s))
    throw Error("ground truth",
                std::string(which) + " time " + std::to_string(time_s) +
                    " s lies outside the interval the scene's motion was compiled for [" +
                    std::to_string(compiled.open_s) + ", " + std::to_string(compiled.close_s) +
                    "] s");
}

}  // namespace

GroundTruthBuffer render_ground_truth(const TraceScene& scene, const SurfaceMotion& motion,
                                      const Camera& camera, const GroundTruthTimes& times,
                                      const std::atomic<bool>* cancel) {
  if (scene.has_motion()) {
    // The last line exposes a readout later.
    const double readout = camera.exposure_interval().close_s - camera.shutter.close_s;
    check_time(scene.shutter(), times.first_s, "first");
    check_time(scene.shutter(), times.second_s, "second");
    check_time(scene.shutter(), times.first_s + readout, "first (last line)");
    check_time(scene.shutter(), times.second_s + readout, "second (last line)");
  }
  const Bounds2i crop = camera.film.crop_pixels();
  const PreparedCamera prepared = camera.prepare();
  GroundTruthBuffer buffer(crop.width(), crop.height());
  for_each_tile_parallel(
      Bounds2i{{0, 0}, {crop.width(), crop.height()}}, kTileSize, [&](const Bounds2i& tile) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return;
        for (int y = tile.min.y; y < tile.max.y; ++y)
          for (int x = tile.min.x; x < tile.max.x; ++x) {
            const Point2d film_point(crop.min.x + x + 0.5, crop.min.y + y + 0.5);
            // A rolling shutter sees this pixel's line later in both exposures.
            const double delay = camera.readout_delay_s(film_point);
            const double t0 = times.first_s + delay, t1 = times.second_s + delay;
            buffer.set_time(x, y, t0);
            if (std::optional<CentreHit> c = centre_hit(scene, prepared, film_point, t0)) {
              const SurfaceHit& h = c->hit;
              buffer.set_surface(x, y,
                                 {.z_m = optical_axis_depth(prepared, c->position, t0),
                                  .range_m = length(c->position - c->ray.origin),
                                  .position = c->position,
                                  .shading_normal = normalize(to_double(h.shading_normal)),
                                  .geometric_normal = normalize(to_double(h.geometric_normal)),
                                  .instance = int(h.mesh),
                                  .material = int(h.material)});
              auto at = [&](double t) {
                return motion.follow(h.mesh, h.primitive, c->position, t0, t);
              };
              buffer.set_forward_flow(x, y, optical_flow(prepared, film_point, at, times.second_s));
            }
            if (std::optional<CentreHit> c = centre_hit(scene, prepared, film_point, t1)) {
              auto at = [&](double t) {
                return motion.follow(c->hit.mesh, c->hit.primitive, c->position, t1, t);
              };
              buffer.set_backward_flow(x, y, optical_flow(prepared, film_point, at, times.first_s));
            }
          }
      });
  return buffer;
}

}  // namespace obscura

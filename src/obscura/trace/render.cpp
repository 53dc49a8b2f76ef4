#include "obscura/trace/render.h"

#include <chrono>
#include <mutex>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

RenderStats render(const TraceScene& scene, const Camera& camera, const Integrator& integrator,
                   const RenderSettings& settings, Film& film, const ProgressCallback& progress) {
  if (settings.samples_per_pixel <= 0)
    throw Error("samples per pixel", "must be positive; got " +
                                         std::to_string(settings.samples_per_pixel));
  if (film.width() != camera.width || film.height() != camera.height)
    throw Error("film and camera resolutions differ");
  auto start = std::chrono::steady_clock::now();
  RenderStats stats;
  std::mutex stats_mutex;

  for_each_tile_parallel(film.bounds(), settings.tile_size, [&](const Bounds2i& tile) {
    RayCounts counts;
    for (int y = tile.min.y; y < tile.max.y; ++y) {
      for (int x = tile.min.x; x < tile.max.x; ++x) {
        for (int s = 0; s < settings.samples_per_pixel; ++s) {
          PixelSampler sampler(settings.seed, {x, y}, uint32_t(s));
          // A box filter one pixel wide: a uniform point in the pixel's square.
          Point2f jitter = sampler.next_2d();
          Ray ray = camera.generate_ray({float(x) + jitter.x, float(y) + jitter.y});
          film.add_sample({x, y}, integrator.radiance(scene, ray, sampler, counts));
        }
      }
    }
    std::lock_guard lock(stats_mutex);
    stats.rays += counts;
  }, progress);

  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace obscura

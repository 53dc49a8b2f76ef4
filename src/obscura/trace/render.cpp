#include "obscura/trace/render.h"

#include <chrono>
#include <mutex>
#include <string>

#include "obscura/camera/pixel_filter.h"
#include "obscura/math/error.h"

namespace obscura {

RenderStats render(const TraceScene& scene, const Camera& camera, const Integrator& integrator,
                   const RenderSettings& settings, Film& film, const ProgressCallback& progress) {
  if (settings.samples_per_pixel <= 0)
    throw Error("samples per pixel",
                "must be positive; got " + std::to_string(settings.samples_per_pixel));
  camera.validate();
  Bounds2i crop = camera.film.crop_pixels();
  if (film.width() != crop.width() || film.height() != crop.height())
    throw Error("render", "the film (" + std::to_string(film.width()) + "x" +
                              std::to_string(film.height()) + ") must match the camera's crop (" +
                              std::to_string(crop.width()) + "x" + std::to_string(crop.height()) +
                              ")");
  const FilterSampler filter(camera.film.filter);
  const auto exposure = float(camera.exposure_scale());
  auto start = std::chrono::steady_clock::now();
  RenderStats stats;
  std::mutex stats_mutex;

  for_each_tile_parallel(
      film.bounds(), settings.tile_size,
      [&](const Bounds2i& tile) {
        RayCounts counts;
        for (int y = tile.min.y; y < tile.max.y; ++y) {
          for (int x = tile.min.x; x < tile.max.x; ++x) {
            // Random numbers are keyed on the full image's pixel, so a crop renders exactly the
            // pixels the full render would.
            Point2i pixel{x + crop.min.x, y + crop.min.y};
            for (int s = 0; s < settings.samples_per_pixel; ++s) {
              Sampler sampler(settings.sampler, settings.seed, pixel, uint32_t(s));
              // 1. A film point around the pixel centre, distributed as the reconstruction filter.
              Point2f u_filter = sampler.next_2d();
              FilterSample fs = filter.sample({u_filter.x, u_filter.y});
              Point2d film_point(pixel.x + 0.5 + fs.offset_px.x, pixel.y + 0.5 + fs.offset_px.y);
              // 2. A point on the lens and a time in the shutter interval.
              Point2f u_lens = sampler.next_2d();
              double time = camera.shutter.time_at(sampler.next_1d());
              // 3. The radiance along the ray, exposed, into this pixel with the filter's weight.
              std::optional<CameraRay> ray =
                  camera.generate_ray(film_point, {u_lens.x, u_lens.y}, time);
              Rgb radiance =
                  ray ? integrator.radiance(scene, ray->to_ray(), sampler, counts) : Rgb();
              film.add_sample({x, y}, radiance * exposure, float(fs.weight));
            }
          }
        }
        std::lock_guard lock(stats_mutex);
        stats.rays += counts;
      },
      progress);

  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace obscura

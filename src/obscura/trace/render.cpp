#include "obscura/trace/render.h"

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "obscura/camera/camera_sample.h"
#include "obscura/camera/pinhole_rays.h"
#include "obscura/color/rgb_to_spectrum.h"
#include "obscura/film/pass_schedule.h"
#include "obscura/math/error.h"
#include "obscura/scene/ground_truth.h"

namespace obscura {

RenderStats render(const TraceScene& scene, const Camera& camera, const Integrator& integrator,
                   const RenderSettings& settings, Film& film, const ProgressCallback& progress,
                   AovBuffers* aovs) {
  if (settings.samples_per_pixel <= 0)
    throw Error("samples per pixel",
                "must be positive; got " + std::to_string(settings.samples_per_pixel));
  if (settings.time_limit_s < 0)
    throw Error("time limit", "must be ≥ 0 seconds; got " + std::to_string(settings.time_limit_s));
  if (settings.spectral && !integrator.supports_spectral())
    throw Error("spectral rendering", "only the path tracer renders spectrally");
  camera.validate();
  Bounds2i crop = camera.film.crop_pixels();
  if (film.width() != crop.width() || film.height() != crop.height())
    throw Error("render", "the film (" + std::to_string(film.width()) + "x" +
                              std::to_string(film.height()) + ") must match the camera's crop (" +
                              std::to_string(crop.width()) + "x" + std::to_string(crop.height()) +
                              ")");
  const Shutter exposed = camera.exposure_interval();
  if (scene.has_motion() &&
      (exposed.open_s != scene.shutter().open_s || exposed.close_s != scene.shutter().close_s))
    throw Error("render", "the scene's object motion was compiled for the shutter [" +
                              std::to_string(scene.shutter().open_s) + ", " +
                              std::to_string(scene.shutter().close_s) +
                              "] s but the camera exposes over [" + std::to_string(exposed.open_s) +
                              ", " + std::to_string(exposed.close_s) +
                              "] s; build the TraceScene with this camera's exposure interval");
  const PreparedCamera prepared_camera = camera.prepare(/*for_many_rays=*/true);
  const std::optional<PinholeRays> pinhole = PinholeRays::of(camera);
  const CameraSampleOrder camera_samples(camera, scene.has_motion(), settings.spectral);
  const auto exposure = float(camera.exposure_scale());
  // Spectral mode's tables are built once per process, before the clock starts, so that the
  // render's time is its samples' (the RGB → spectrum fit takes about half a second of CPU).
  if (settings.spectral) {
    RgbToSpectrumTable::working_space();
    SampledWavelengths::sample(0.5f);
  }
  if (settings.share.parts < 1 || settings.share.part < 0 ||
      settings.share.part >= settings.share.parts)
    throw Error("render", "part " + std::to_string(settings.share.part) + " of " +
                              std::to_string(settings.share.parts) + " does not exist");
  std::vector<Bounds2i> tiles;
  {
    std::vector<Bounds2i> all = make_tiles(film.bounds(), settings.tile_size);
    for (size_t t = 0; t < all.size(); ++t)
      if (settings.share.owns_tile(int(t))) tiles.push_back(all[t]);
  }
  RenderStats stats;
  std::mutex stats_mutex;

  auto render_samples = [&](const Bounds2i& tile, int first_sample, int end_sample) {
    RayCounts counts;
    for (int y = tile.min.y; y < tile.max.y; ++y) {
      for (int x = tile.min.x; x < tile.max.x; ++x) {
        // Random numbers are keyed on the full image's pixel, so a crop renders exactly the
        // pixels the full render would.
        Point2i pixel{x + crop.min.x, y + crop.min.y};
        const double delay = camera_samples.pixel_delay_s(pixel);
        SobolPixelKeys keys(settings.seed, pixel);
        for (int s = first_sample; s < end_sample; ++s) {
          Sampler sampler = settings.sampler == SamplerType::kSobol
                                ? Sampler(settings.sampler, settings.seed, pixel, uint32_t(s), keys)
                                : Sampler(settings.sampler, settings.seed, pixel, uint32_t(s));
          // 1. The camera's numbers: film point, lens point, time, wavelengths (in that order).
          const CameraSample cs = camera_samples.draw(sampler, pixel, delay);
          std::optional<SampledWavelengths> wavelengths;
          if (settings.spectral) wavelengths = SampledWavelengths::sample(cs.wavelength_u);
          // A dispersive lens sends each wavelength its own way: the ray is the hero's, and the
          // companions, which would have left the lens elsewhere, end here.
          double camera_nm = kWavelengthD_nm;
          if (wavelengths && prepared_camera.disperses()) {
            camera_nm = wavelengths->hero_nm();
            wavelengths->terminate_secondary();
          }
          // 2. The radiance along the ray, exposed, into this pixel with the filter's weight.
          std::optional<Ray> ray;
          float ray_weight = 1;
          if (pinhole) {
            ray = pinhole->generate(cs.film_point, cs.time_s);
          } else if (std::optional<CameraRay> r = prepared_camera.generate_ray(
                         cs.film_point, {cs.lens.x, cs.lens.y}, cs.time_s, camera_nm)) {
            ray = r->to_ray();
            ray_weight = float(r->weight);
          }
          FirstHit first;
          FirstHit* first_hit = aovs ? &first : nullptr;
          Rgb radiance;
          if (ray && wavelengths)
            radiance = wavelengths->to_working_rgb(integrator.spectral_radiance(
                scene, *ray, *wavelengths, sampler, counts, first_hit));
          else if (ray)
            radiance = integrator.radiance(scene, *ray, sampler, counts, first_hit);
          film.add_sample({x, y}, radiance * (exposure * ray_weight), float(cs.filter_weight));
          if (aovs)
            aovs->add_sample({x, y}, first.hit, first.albedo, first.normal,
                             // ground truth's Z (scene/ground_truth.h) at the sample's time
                             first.hit ? float(optical_axis_depth(
                                             prepared_camera, Point3d(first.position), cs.time_s))
                                       : 0.f,
                             first.range, first.id);
        }
      }
    }
    std::lock_guard lock(stats_mutex);
    stats.rays += counts;
  };

  // Passes over every tile (film/pass_schedule.h), up to 64 samples each.
  PassSchedule passes(
      settings.samples_per_pixel, 64, OnCancel::kAbandonPass,
      {.time_limit_s = settings.time_limit_s, .cancel = settings.cancel, .share = &settings.share});
  const int tile_count = int(tiles.size());
  Pass pass;
  while (passes.next(pass)) {
    for_each_tile_parallel(
        tiles,
        [&](const Bounds2i& tile) {
          if (!passes.cancel_requested()) render_samples(tile, pass.first, pass.end);
        },
        progress ? ProgressCallback([&](int tiles_done, int) {
          passes.report(progress, pass, tiles_done, tile_count);
        })
                 : ProgressCallback());
    passes.finish(pass);
  }
  stats.cancelled = passes.cancelled();
  stats.partial = passes.cancelled() || passes.time_limited();
  stats.samples_per_pixel = passes.done();
  stats.seconds = passes.seconds();
  return stats;
}

}  // namespace obscura

#include "obscura/trace/render.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include "obscura/camera/pinhole_rays.h"
#include "obscura/camera/pixel_filter.h"
#include "obscura/color/rgb_to_spectrum.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool cancelled(const RenderSettings& settings) {
  return settings.cancel && settings.cancel->load(std::memory_order_relaxed);
}

}  // namespace

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
  const FilterSampler filter(camera.film.filter);
  const auto exposure = float(camera.exposure_scale());
  // Which of the camera's numbers change the image: the lens point only with depth of field or a
  // lens system, the time only where something moves during the shutter. The others are skipped,
  // not drawn (most of a sample's sampler cost where camera rays escape to the environment); a
  // still scene's rays all carry the shutter's middle.
  const bool lens_matters = camera.uses_lens_samples();
  const bool time_matters = scene.has_motion() || camera.world_from_camera.is_animated();
  const double still_time = camera.shutter.time_at(0.5);
  // Spectral mode's tables are built once per process, before the clock starts, so that the
  // render's time is its samples' (the RGB → spectrum fit takes about half a second of CPU).
  if (settings.spectral) {
    RgbToSpectrumTable::working_space();
    SampledWavelengths::sample(0.5f);
  }
  auto start = Clock::now();
  RenderStats stats;
  std::mutex stats_mutex;
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
  const int tile_count = int(tiles.size());
  const int spp = settings.samples_per_pixel;

  auto render_samples = [&](const Bounds2i& tile, int first_sample, int end_sample) {
    RayCounts counts;
    for (int y = tile.min.y; y < tile.max.y; ++y) {
      for (int x = tile.min.x; x < tile.max.x; ++x) {
        // Random numbers are keyed on the full image's pixel, so a crop renders exactly the
        // pixels the full render would.
        Point2i pixel{x + crop.min.x, y + crop.min.y};
        // A rolling shutter exposes the pixel's sensor line later: every sample of the pixel
        // takes its line's delay.
        const double delay = camera.readout_delay_s({pixel.x + 0.5, pixel.y + 0.5});
        SobolPixelKeys keys(settings.seed, pixel);
        for (int s = first_sample; s < end_sample; ++s) {
          Sampler sampler = settings.sampler == SamplerType::kSobol
                                ? Sampler(settings.sampler, settings.seed, pixel, uint32_t(s), keys)
                                : Sampler(settings.sampler, settings.seed, pixel, uint32_t(s));
          // 1. A film point around the pixel centre, distributed as the reconstruction filter.
          Point2f u_filter = sampler.next_2d();
          FilterSample fs = filter.sample({u_filter.x, u_filter.y});
          Point2d film_point(pixel.x + 0.5 + fs.offset_px.x, pixel.y + 0.5 + fs.offset_px.y);
          // 2. A point on the lens and a time in the shutter interval.
          Point2f u_lens{0.5f, 0.5f};
          if (lens_matters)
            u_lens = sampler.next_2d();
          else
            sampler.skip_2d();
          double time = still_time + delay;
          if (time_matters)
            time = camera.shutter.time_at(sampler.next_1d()) + delay;
          else
            sampler.skip_1d();
          // 3. Spectral mode: the sample's wavelengths, drawn before its ray so that a camera
          //    whose optics disperse can be given the hero wavelength.
          std::optional<SampledWavelengths> wavelengths;
          if (settings.spectral) wavelengths = SampledWavelengths::sample(sampler.next_1d());
          // A dispersive lens sends each wavelength its own way: the ray is the hero's, and the
          // companions, which would have left the lens elsewhere, end here.
          double camera_nm = kWavelengthD_nm;
          if (wavelengths && prepared_camera.disperses()) {
            camera_nm = wavelengths->hero_nm();
            wavelengths->terminate_secondary();
          }
          // 4. The radiance along the ray, exposed, into this pixel with the filter's weight.
          std::optional<Ray> ray;
          float ray_weight = 1;
          if (pinhole) {
            ray = pinhole->generate(film_point, time);
          } else if (std::optional<CameraRay> r = prepared_camera.generate_ray(
                         film_point, {u_lens.x, u_lens.y}, time, camera_nm)) {
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
          film.add_sample({x, y}, radiance * (exposure * ray_weight), float(fs.weight));
          if (aovs)
            aovs->add_sample({x, y}, first.hit, first.albedo, first.normal, first.depth, first.id);
        }
      }
    }
    std::lock_guard lock(stats_mutex);
    stats.rays += counts;
  };

  // Passes of 1, 1, 2, 4, … samples (at most 64), each over every tile.
  int done = 0;
  int pass_size = 1;
  while (done < spp) {
    int end = std::min(spp, done + pass_size);
    double pass_start = seconds_since(start);
    int pass_first = done;
    for_each_tile_parallel(
        tiles,
        [&](const Bounds2i& tile) {
          if (!cancelled(settings)) render_samples(tile, pass_first, end);
        },
        progress ? ProgressCallback([&](int tiles_done, int) {
          // Progress in samples × tiles over the whole render, in 64 bits (a time-limited render
          // asks for up to 2^30 samples) and scaled down to fit the callback's int.
          const int64_t total = int64_t(spp) * tile_count;
          const int64_t now =
              int64_t(pass_first) * tile_count + int64_t(end - pass_first) * tiles_done;
          const int64_t scale = total / std::numeric_limits<int>::max() + 1;
          progress(int(now / scale), int(total / scale));
        })
                 : ProgressCallback());
    // This process's verdict, then the team's: cancelled, or would the next pass (about twice as
    // long as this one) overrun the time limit?
    StopVerdict own = StopVerdict::kGoOn;
    const int next_pass_size = end > 1 ? std::min(64, pass_size * 2) : pass_size;
    if (cancelled(settings)) {
      own = StopVerdict::kCancelled;
    } else if (end < spp && settings.time_limit_s > 0) {
      double now = seconds_since(start), pass_seconds = now - pass_start;
      double next_seconds =
          pass_seconds * std::min(spp - end, next_pass_size) / std::max(1, end - pass_first);
      if (now + next_seconds > settings.time_limit_s) own = StopVerdict::kTimeLimit;
    }
    const StopVerdict verdict = settings.share.agree(own);
    if (verdict == StopVerdict::kCancelled) {
      stats.cancelled = stats.partial = true;
      break;
    }
    done = end;
    pass_size = next_pass_size;
    if (verdict == StopVerdict::kTimeLimit) {
      stats.partial = true;
      break;
    }
  }
  stats.samples_per_pixel = done;
  stats.seconds = seconds_since(start);
  return stats;
}

}  // namespace obscura

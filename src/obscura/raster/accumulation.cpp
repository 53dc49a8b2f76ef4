#include "obscura/raster/accumulation.h"

#include <cmath>
#include <limits>
#include <string>

#include "obscura/camera/vignetting.h"
#include "obscura/film/pass_schedule.h"
#include "obscura/math/error.h"
#include "obscura/math/rng.h"
#include "obscura/math/sobol.h"

namespace obscura::raster {

namespace {

constexpr double kMillimetresPerMetre = 1000;

// A 32-bit fraction as a double in [0, 1), keeping all 32 bits.
double fraction_to_double(uint32_t bits) {
  return bits * 0x1p-32;
}

}  // namespace

std::vector<LensTimeSample> accumulation_samples(const Camera& camera, int count, uint64_t seed) {
  if (count < 1)
    throw Error("accumulation.samples", "must be at least 1; got " + std::to_string(count));
  if (count == 1) return {{{0.5, 0.5}, camera.shutter.time_at(0.5)}};
  // One independent Owen scramble per dimension keeps the Sobol' points' stratification while
  // making each seed's set a different one.
  uint32_t scramble[3];
  for (int d = 0; d < 3; ++d) scramble[d] = uint32_t(hash_words(seed, 0xacc0u, uint64_t(d)));
  std::vector<LensTimeSample> samples(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    double u[3];
    for (int d = 0; d < 3; ++d)
      u[d] = fraction_to_double(owen_scramble(sobol_bits(uint32_t(i), d), scramble[d]));
    samples[size_t(i)] = {{u[0], u[1]}, camera.shutter.time_at(u[2])};
  }
  return samples;
}

AccumulationStats accumulate(const Camera& camera, const AccumulationSettings& settings,
                             const FrameRenderer& render_frame, Film& film,
                             const ProgressCallback& progress, RenderTarget* middle_frame) {
  camera.validate();
  if (!camera.has_projection_matrix())
    throw Error("accumulation.camera", "the rasterizer needs a perspective or orthographic camera");
  if (!(settings.time_limit_s >= 0)) throw Error("accumulation.time_limit", "must be ≥ 0 seconds");
  std::vector<LensTimeSample> samples =
      accumulation_samples(camera, settings.samples, settings.seed);
  if (!settings.depth_of_field)
    for (LensTimeSample& s : samples) s.lens_sample = {0.5, 0.5};
  // Frames are the rasterizer's samples: one per pass, paced and stopped as every renderer's
  // passes are (film/pass_schedule.h).
  PassSchedule passes(
      settings.samples, 1, OnCancel::kCompletePass,
      {.time_limit_s = settings.time_limit_s, .cancel = settings.cancel, .share = &settings.share});
  // The frame kept: the one nearest mid-shutter (the first of equals) among those drawn, so a
  // render stopped early still has one.
  const double middle = camera.shutter.time_at(0.5);
  double kept_distance = std::numeric_limits<double>::infinity();

  // A lens barrel (mechanical vignetting) stops some lens points' rays to some pixels: each
  // frame's pixels are kept or dropped as the tracer keeps or stops its ray through that lens
  // point (the cat-eye of off-axis bokeh), so the light it loses is in the frames already.
  const bool barrel =
      settings.depth_of_field && camera.lens.depth_of_field && camera.lens.vignetting.mechanical();
  std::vector<Point2d> windows;
  std::vector<float> kept;
  if (barrel) {
    const PreparedCamera prepared = camera.prepare();
    const Bounds2i crop = camera.film.crop_pixels();
    windows.resize(size_t(film.width()) * size_t(film.height()));
    kept.resize(windows.size());
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x)
        windows[size_t(y) * size_t(film.width()) + size_t(x)] =
            prepared.window_from_raster({crop.min.x + x + 0.5, crop.min.y + y + 0.5});
  }
  AccumulationStats stats;
  RenderTarget target(film.width(), film.height(), settings.msaa_samples, settings.aovs);
  target.set_share(settings.share.part, settings.share.parts);
  Pass pass;
  while (passes.next(pass)) {
    const int i = pass.first;
    FrameParameters frame;
    frame.index = i;
    frame.sample = samples[size_t(i)];
    frame.lens = lens_view(camera, frame.sample.lens_sample, frame.sample.time_s);
    target.clear();
    render_frame(frame, target);
    if (barrel) {
      const Point2d lens_mm(frame.lens.lens_point_m.x * kMillimetresPerMetre,
                            frame.lens.lens_point_m.y * kMillimetresPerMetre);
      const double focus_mm = camera.lens.focus_distance_m * kMillimetresPerMetre;
      for (size_t p = 0; p < windows.size(); ++p)
        kept[p] = passes_barrel(camera.lens.vignetting, lens_mm, windows[p], focus_mm) ? 1.f : 0.f;
      target.accumulate_into(film, kept);
    } else {
      target.accumulate_into(film);
    }
    double distance = std::abs(frame.sample.time_s - middle);
    if (middle_frame && distance < kept_distance) {
      *middle_frame = target;
      kept_distance = distance;
    }
    passes.finish(pass);
    stats.frames = passes.done();
    if (progress) progress(stats.frames, settings.samples);
  }
  stats.cancelled = passes.cancelled();
  stats.time_limited = passes.time_limited();
  return stats;
}

bool has_motion_blur(const Camera& camera, bool scene_moves) {
  bool moves = scene_moves || camera.world_from_camera.is_animated();
  return camera.shutter.duration_s() > 0 && moves;
}

bool needs_accumulation(const Camera& camera, bool scene_moves) {
  return camera.lens.depth_of_field || has_motion_blur(camera, scene_moves);
}

}  // namespace obscura::raster

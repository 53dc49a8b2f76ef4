// Depth of field and motion blur by accumulation (the "accumulation buffer" of Haeberli and
// Akeley 1990): the scene is rendered N times, each time through another point of the lens and
// at another instant of the shutter interval, and the renders are averaged into the film.
//
// Each frame's view and projection come from lens_view (camera/lens_view.h), so frame i images
// the scene exactly as the tracer's rays with the same lens sample and time do. The N (lens,
// time) samples are the first N points of a 3D Sobol' sequence, Owen-scrambled by the seed: the
// lens points and the times are each stratified (for N a power of two, exactly one time in each
// 1/N of the shutter) and jointly low-discrepancy, and the same seed gives the same samples.
//
// The loop knows nothing about scenes: a frame callback draws whatever the caller has (a scene,
// test geometry) with the matrices it is given, at the time it is given (object motion is the
// callback's business). It is called for the frames in order, one after the other (each draw is
// parallel inside), and every pixel sums its frames in that order, so the result is
// bit-identical for any thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/camera/lens_view.h"
#include "obscura/film/film.h"
#include "obscura/film/tiles.h"
#include "obscura/film/work_share.h"
#include "obscura/raster/render_target.h"

namespace obscura::raster {

// One accumulation sample: where on the lens (∈ [0,1)², warped onto the aperture as the tracer
// warps it) and when (seconds, inside the shutter interval).
struct LensTimeSample {
  Point2d lens_sample;
  double time_s = 0;
};

// The frame a callback is asked to draw.
struct FrameParameters {
  int index = 0;  // 0 … samples − 1
  LensTimeSample sample;
  LensView lens;  // view, projection and eye for this lens point and time
  Matrix4 clip_from_world() const { return lens.projection * lens.view; }
};

struct AccumulationSettings {
  int samples = 16;  // renders averaged, ≥ 1
  uint64_t seed = 0;
  int msaa_samples = 1;  // of each frame's render target: 1, 4 or 8
  bool aovs = false;     // whether each frame's render target keeps AOVs
  // Off: every frame looks through the lens centre (motion blur only, or a sharp image for a
  // post-process), with the camera's framing unchanged.
  bool depth_of_field = true;
  // Stopping early (after at least one frame): when *cancel becomes true (Ctrl-C), or before a
  // frame that would end past time_limit_s seconds (0 = none), by the rule every renderer's
  // passes follow (film/pass_schedule.h: each frame is a pass).
  const std::atomic<bool>* cancel = nullptr;
  double time_limit_s = 0;
  // Several processes drawing the frames together: each rasterizes its share's tiles of every
  // frame (RenderTarget::set_share) and settles with the others after each frame, so that all
  // stop after the same frame. Default: alone.
  WorkShare share = {};
};

// What accumulate() did: frames drawn (== settings.samples unless it stopped early) and why it
// stopped early, if it did.
struct AccumulationStats {
  int frames = 0;
  bool cancelled = false;
  bool time_limited = false;
  bool partial() const { return cancelled || time_limited; }
};

// Draws one frame into `target`, which arrives cleared (black, depth 1) and has the film's size.
// The radiance written should already carry the camera's exposure scale.
using FrameRenderer = std::function<void(const FrameParameters&, RenderTarget&)>;

// The N samples: the first N points of the scrambled 3D Sobol' sequence (lens x, lens y, time),
// mapped into the shutter interval. A single sample is the lens centre at mid-shutter: the
// pinhole image at mid-exposure. Throws obscura::Error for count < 1.
std::vector<LensTimeSample> accumulation_samples(const Camera& camera, int count, uint64_t seed);

// Renders settings.samples frames through `render_frame` and adds their mean to `film` (each
// pixel receives one sample of weight 1 per frame). With `middle_frame` given, it receives a
// copy of the render target of the frame nearest mid-shutter among those drawn: its view depth
// for a depth-of-field post-process, its AOVs for the id/depth/normal outputs. Throws
// obscura::Error for a camera without a projection matrix or bad settings. `progress` is called
// after each frame. Stopped early, the film holds the mean of the frames drawn.
AccumulationStats accumulate(const Camera& camera, const AccumulationSettings& settings,
                             const FrameRenderer& render_frame, Film& film,
                             const ProgressCallback& progress = {},
                             RenderTarget* middle_frame = nullptr);

// Whether anything blurs with motion: the shutter is open for a while and the camera or something
// in the caller's scene moves.
bool has_motion_blur(const Camera& camera, bool scene_moves);
// Whether the camera or the caller's scene needs more than one frame: the lens has depth of
// field, or there is motion blur.
bool needs_accumulation(const Camera& camera, bool scene_moves);

}  // namespace obscura::raster

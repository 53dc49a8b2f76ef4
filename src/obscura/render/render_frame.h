// One frame by any renderer, through one call: what the command line and the Python module
// share. It renders through the renderer's back end (render/renderer_backend.h) in a session
// that lives for the frame (render/render_session.h keeps one for many).
#pragma once

#include <optional>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/film/image.h"
#include "obscura/film/tiles.h"
#include "obscura/render/frame_finish.h"
#include "obscura/render/frame_settings.h"
#include "obscura/render/lens_flare.h"

namespace obscura {

// Renders `camera` over `scene` into `film` (the camera's crop size) and, if given, `aovs` (same
// size; the rasterizer replaces them by buffers without albedo): the film as the renderer leaves
// it, before finishing. Throws obscura::Error for invalid settings (samples or max depth out of
// range) or sizes.
FrameStats render_frame(const Scene& scene, const Camera& camera, const FrameSettings& settings,
                        Film& film, AovBuffers* aovs = nullptr,
                        const ProgressCallback& progress = {});

// A frame as rendered, with what finishes it: every door (the command line, MPI ranks, shards,
// sequences, Python) renders through this and finishes through finished().
struct RenderedFrame {
  Renderer renderer = {};
  Image film_sums;  // Film::sums(): Σ w·L and Σ w per pixel
  std::optional<AovBuffers> aovs;
  std::vector<AovImage> layers;  // finishing's per-pixel inputs (render/frame_finish.h)
  FrameFinish finish;
  FrameStats stats;
  FlareStats flare_stats;

  // The finished frame, linear RGB (finish_frame): only on the whole frame, not a part.
  // With `cancel`, a glare not done when it is set is left out and `*unfinished` set.
  Image finished(const std::atomic<bool>* cancel = nullptr, bool* unfinished = nullptr) const {
    return finish_frame(film_sums, layers, finish, cancel, unfinished);
  }
};

// Renders the frame and prepares its finishing: the post-process depth of field's layer, the
// flare's (computed before rendering, so that a camera without a lens system fails first) and the
// glare's optics. With `aovs`, the frame's AOVs. Throws obscura::Error as above, and for glare or
// flare on a camera that has none.
RenderedFrame render_frame(const Scene& scene, const Camera& camera, const FrameSettings& settings,
                           bool aovs, const ProgressCallback& progress = {});

}  // namespace obscura

// One frame of `obscura render`, from a loaded scene to the images to write, as either renderer
// leaves it: the film's sums and the auxiliary images. A frame rendered in parts (MPI ranks,
// --shard) is assembled from its parts' frames before it is finished and written.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/film/image.h"
#include "obscura/film/tiles.h"
#include "obscura/film/work_share.h"
#include "obscura/render/lens_flare.h"
#include "obscura/render/render_frame.h"
#include "obscura/render/render_session.h"
#include "obscura/scene/scene.h"
#include "partial_render.h"
#include "render_options.h"
#include "team.h"

namespace obscura::app {

// The library's frame (film sums, AOVs, finishing layers and recipe) with how the render ended,
// as the command line reports it.
struct RenderedFrame : obscura::RenderedFrame {
  RenderProgress progress;
  std::vector<std::string> warnings;
  double seconds = 0;               // this process's
  double rays = 0;                  // tracer: rays this process traced
  bool time_limit_reached = false;  // a time limit without --spp ended the (complete) render
};

// Checks the options, loads the scene and resolves its camera as the options say; with
// `writes_output`, checks before any work that the output (and the auxiliary images) can be
// written and would not replace an input. The scene file's own settings (size, samples, seed)
// fill in what the command line did not give.
Scene prepare_scene(RenderOptions& options, bool writes_output);

// Checks the options and resolves what they name (the renderer's row among them): what
// load_render_scene does first. A sequence calls it once on the options every frame copies.
void resolve_render_options(RenderOptions& options);

// prepare_scene in two steps, for a sequence that loads its scene once: the scene as the options
// load it (its own camera kept), then each frame's camera over it, with the checks that need it.
Scene load_render_scene(RenderOptions& options, bool writes_output);
Camera resolve_render_camera(const Scene& scene, RenderOptions& options, bool writes_output,
                             std::vector<std::string>* notes);

// Whether ghost flares are asked for: --flare, or the scene file's render.flare.
bool flare_requested(const RenderOptions& options, const SceneRenderSettings& scene);

// How the renderer's tiles are dealt to `parts` parts (the tracer's 16-pixel tiles, the
// rasterizer's 64-pixel bins).
TileDeal tile_deal(Renderer renderer, int width, int height, int parts);

// The library's settings for the options (validated by prepare_scene) and the scene file's
// render settings, the tiles `share` owns.
FrameSettings frame_settings(const RenderOptions& options, const SceneRenderSettings& scene,
                             const WorkShare& share);

// Renders the scene with its camera (resolved by the options), the tiles `share` owns, through
// the library's render_frame.
RenderedFrame render_frame(const Scene& scene, const RenderOptions& options, const WorkShare& share,
                           const ProgressCallback& progress = {});
// The same through a session that keeps what it compiled of its scene for the next frame.
RenderedFrame render_frame(RenderSession& session, const Camera& camera,
                           const RenderOptions& options, const WorkShare& share,
                           const ProgressCallback& progress = {});

// Rank 0 receives every rank's pixels of the film, the auxiliary images and the finishing layers
// (rank = part).
void gather_frame(Team& team, RenderedFrame& frame);

// Writes the image (marked partial when it is) and the auxiliary images beside it; prints the
// paths on stdout (the image first) and sets the exit status that says how the render ended;
// returns that ending. A cancel (InterruptGuard) during the glare leaves it out and marks the
// image interrupted; one during the writing still ends the command as interrupted.
RenderEnd write_frame(const RenderOptions& options, const std::string& output,
                      const RenderedFrame& frame);

}  // namespace obscura::app

// What the render_* fuzz targets do with a scene and a camera their input made: render a tiny
// frame (a crop window of at most 8 × 8 pixels, 1 sample per pixel) with both renderers, the path
// tracer and the rasterizer, finish it (glare, flare where asked, with small settings), and compute
// its ground truth. Everything the input could make expensive is clamped here so that one input
// stays well under libFuzzer's 10 s: the film's size, the samples, the depth, the shadow maps, the
// frames accumulated, the glare's radius, the flare's grids, the flare's work and the scene's size.
//
// An obscura::Error is the expected outcome for a scene or a camera a renderer refuses. A
// non-finite pixel in a finished frame is a finding (the renderers promise finite output for
// every scene that validates): the target aborts with the renderer's name.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <variant>

#include "obscura/camera/camera.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/math/error.h"
#include "obscura/render/frame_request.h"
#include "obscura/render/lens_flare.h"
#include "obscura/render/render_session.h"
#include "obscura/render/renderer.h"
#include "obscura/scene/ground_truth.h"
#include "obscura/scene/scene.h"

namespace obscura::fuzz {

inline constexpr int kMaxSide = 8;
// Beyond this the scene's acceleration structures alone take seconds under the sanitizers.
inline constexpr size_t kMaxTriangles = 20'000;
// Ghosts × sources × surfaces the flare may trace (the CLI allows 500,000: minutes here).
inline constexpr long long kMaxFlareWork = 2'000;

// Pixels [⌈size·low⌉, ⌈size·high⌉) of a crop window's side (film_geometry.h); -1 when the
// window is not a valid one (validate refuses it).
inline long long crop_side(int size, double low, double high) {
  if (!(low >= 0 && low < high && high <= 1)) return -1;
  return (long long)std::ceil(size * high) - (long long)std::ceil(size * low);
}

// A window of at most kMaxSide pixels a side at the film's centre, in place of a crop window
// that covers more: the camera keeps its resolution, field of view and pixel pitch (what the
// glare's PSF is sized by: a film of 8 pixels across a 36 mm sensor needs a pattern grid of
// 4096²) and renders only the window.
inline void shrink_film(Camera& camera) {
  FilmGeometry& film = camera.film;
  if (film.width_px <= 0 || film.height_px <= 0) return;  // validate refuses it
  auto shrink = [](int size, double& low, double& high) {
    const long long side = crop_side(size, low, high);
    if (side < 0 || side <= kMaxSide) return;
    const int first = size / 2 - kMaxSide / 2;
    low = double(first) / size;
    high = double(first + kMaxSide) / size;
  };
  shrink(film.width_px, film.crop.x_min, film.crop.x_max);
  shrink(film.height_px, film.crop.y_min, film.crop.y_max);
}

struct TinyRender {
  bool glare = false;  // diffraction glare (radius ≤ 4 px)
  bool flare = false;  // ghost flare (a lens-system camera; tiny grids)
};

// The lens system's surfaces (0 for another projection), for the flare's work bound.
inline long long lens_surfaces(const Camera& camera) {
  const auto* lens = std::get_if<LensSystemProjection>(&camera.projection);
  return lens && lens->lens ? (long long)lens->lens->prescription().surfaces.size() : 0;
}

inline void check_finite(const Image& image, const Renderer& renderer) {
  for (float v : image.data)
    if (!std::isfinite(v)) {
      std::fprintf(stderr, "finding: the %s rendered a non-finite pixel (%g)\n", renderer.name(),
                   double(v));
      std::abort();
    }
}

// The settings of a tiny frame, the scene's own glare and flare wishes (and `what`'s) clamped.
inline FrameSettings tiny_settings(const Scene& scene, const Camera& camera, Renderer renderer,
                                   const TinyRender& what, size_t flare_sources) {
  FrameSettings s;
  s.renderer = renderer;
  s.samples_per_pixel = 1;
  s.max_depth = 6;
  s.raster.shadow_map_size = 64;
  s.raster.effect_samples = 2;
  const ResolvedFrameRequest wish = resolve_frame_request({}, scene.render, renderer);
  s.seed = wish.seed;
  if (wish.glare || what.glare) {
    s.glare = wish.glare.value_or(GlareSettings{});
    s.glare->radius_px = std::clamp(s.glare->radius_px, 1, 4);
  }
  // As render/lens_flare.h counts it: N(N−1)/2 ghosts, each traced per source along N surfaces.
  const long long n = lens_surfaces(camera);
  const long long flare_work = n * (n - 1) / 2 * n * (long long)std::max<size_t>(flare_sources, 1);
  if ((wish.flare || what.flare) && flare_work <= kMaxFlareWork) {
    s.flare = wish.flare.value_or(FlareSettings{});
    s.flare->grid_cells = 4;
    s.flare->search_cells = 4;
  }
  return s;
}

// Renders `scene` through `camera` (its film shrunk) with every renderer; see the file's comment.
inline void render_tiny(const Scene& scene, Camera camera, const TinyRender& what = {}) {
  if (scene.stats().triangles > kMaxTriangles) return;
  shrink_film(camera);
  camera.validate();  // throws obscura::Error for a camera no renderer may use
  size_t sources = 0;
  if (lens_surfaces(camera) > 0) {
    try {
      sources = flare_sources(scene, camera).size();
    } catch (const Error&) {
    }
  }
  RenderSession session(scene);
  for (const Renderer& renderer : {Renderer(), renderer_named("raster")}) {
    const FrameSettings settings = tiny_settings(scene, camera, renderer, what, sources);
    try {
      const RenderedFrame frame = session.render(camera, settings, false);
      check_finite(frame.finished(), renderer);
    } catch (const Error&) {
      // a camera or a finishing step this renderer refuses: the other may still render
    }
    try {
      session.ground_truth(camera, settings, default_ground_truth_times(camera));
    } catch (const Error&) {
    }
  }
}

}  // namespace obscura::fuzz

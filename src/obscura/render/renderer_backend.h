// A renderer's back end: all that Obscura's frame machinery — render sessions, finishing, work
// shares, ground truth, the doors — needs of one renderer. A back end compiles a scene once for
// an exposure interval (an Embree BVH, binned meshes, diced grids: whatever it renders from) and
// renders any number of frames from that compilation; a RenderSession (render/render_session.h)
// keeps compilations alive while they serve. Adding a renderer is a back-end file and a row in
// the table (render/renderer.cpp); docs/architecture.md walks through it.
#pragma once

#include <memory>
#include <span>
#include <string_view>

#include "obscura/camera/shutter.h"
#include "obscura/film/tiles.h"
#include "obscura/render/frame_settings.h"

namespace obscura {

class AovBuffers;
class Film;
class GroundTruthBuffer;
struct Camera;
struct GroundTruthTimes;
struct Scene;

// What a renderer does, so that the doors ask for nothing it lacks and treat it as it needs.
struct RendererCapabilities {
  // Its work per pixel is FrameSettings::samples_per_pixel (and a time limit without a sample
  // count asks for as many as fit); otherwise it decides its own (the rasterizer accumulates
  // FrameSettings::raster.effect_samples frames).
  bool takes_samples_per_pixel = true;
  const char* progress_unit = "samples per pixel";  // what FrameStats::done counts
  bool albedo = false;    // its AOVs include an albedo (every renderer's have normal, depth, id)
  bool spectral = false;  // spectral light transport (FrameSettings::spectral)
  bool ground_truth = false;     // RendererBackend::ground_truth
  bool raster_settings = false;  // it reads FrameSettings::raster (the --raster-* options)
  // The side of the square tiles it renders, which a WorkShare deals to the parts of a frame
  // (film/work_share.h): parts must agree on it to assemble a frame.
  int tile_size = 16;
};

// A scene as one back end renders it, for frames exposed over some interval.
class CompiledScene {
 public:
  virtual ~CompiledScene() = default;
  // Whether frames exposed over `exposure` render from this compilation (a scene where nothing
  // moves serves every exposure).
  virtual bool serves(const Shutter& exposure) const = 0;
  // Brings the compilation up to date in place for frames exposed over `exposure`, after the
  // scene's meshes `changed` were posed again (their counts kept); false where only a new
  // compilation will do (the default).
  virtual bool update(const Scene& /*scene*/, std::span<const uint32_t> /*changed*/,
                      const Shutter& /*exposure*/) {
    return false;
  }
};

class RendererBackend {
 public:
  RendererBackend(const char* name, const char* summary, const RendererCapabilities& capabilities)
      : name_(name), summary_(summary), capabilities_(capabilities) {}
  virtual ~RendererBackend() = default;
  RendererBackend(const RendererBackend&) = delete;
  RendererBackend& operator=(const RendererBackend&) = delete;

  const char* name() const { return name_; }        // as the command line names it
  const char* summary() const { return summary_; }  // a few words for help texts
  const RendererCapabilities& capabilities() const { return capabilities_; }

  // Back ends that compile a scene the same way (the tracer's integrators share an Embree scene)
  // return the same key, and a session compiles once for all of them.
  virtual std::string_view compiled_form() const { return name_; }
  // The scene compiled for frames exposed over `exposure`. `scene` outlives the result.
  virtual std::unique_ptr<CompiledScene> compile(const Scene& scene,
                                                 const Shutter& exposure) const = 0;
  // Renders `camera` (exposed over an interval `compiled` serves) into `film` (the camera's crop
  // size) and, if given, `aovs` (the same size; replaced by buffers without albedo where the
  // renderer has none): the film as rendered, before finishing. Throws obscura::Error for
  // settings out of range or a film of another size.
  virtual FrameStats render(const CompiledScene& compiled, const Camera& camera,
                            const FrameSettings& settings, Film& film, AovBuffers* aovs,
                            const ProgressCallback& progress) const = 0;
  // The ground truth (depth, positions, normals, ids, flow) of `camera` at the pixel centres,
  // from a compilation serving an interval that holds the shutter and both flow times. Renderers
  // without the capability throw obscura::Error.
  // Throws obscura::Error for a camera it cannot give the ground truth of: the doors ask before
  // rendering, so that a bad request fails before the render, not after it.
  virtual void check_ground_truth_camera(const Camera& camera) const;
  virtual GroundTruthBuffer ground_truth(const CompiledScene& compiled, const Camera& camera,
                                         const FrameSettings& settings,
                                         const GroundTruthTimes& times) const;

 private:
  const char* name_;
  const char* summary_;
  RendererCapabilities capabilities_;
};

}  // namespace obscura

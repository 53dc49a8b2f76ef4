// A scene held for many frames: what a renderer's back end compiles of it (render/
// renderer_backend.h: the tracer's Embree scene, its lights and materials) is built once and kept
// while it serves the frames asked for — the frames of a sequence, the parts of a frame, a
// Python loop, later a live view. A scene whose objects do not move over the shutter compiles
// once for any exposure; one whose objects move is brought up to date (or compiled again) when a
// frame's exposure interval differs from the last one's, and a scene posed again at another
// moment (a glTF animation's skins and morph targets: Scene::pose) rebuilds only the meshes
// that changed. Renderers whose back ends compile alike (the tracer's
// integrators) share one compilation.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "obscura/render/render_frame.h"

namespace obscura {

class CompiledScene;
class GroundTruthBuffer;
struct GroundTruthTimes;

class RenderSession {
 public:
  // `scene` must outlive the session, and change only as scene_changed() says.
  explicit RenderSession(const Scene& scene);
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  const Scene& scene() const { return scene_; }

  // As render_frame (render/render_frame.h), over the session's scene, reusing what it compiled.
  FrameStats render(const Camera& camera, const FrameSettings& settings, Film& film,
                    AovBuffers* aovs = nullptr, const ProgressCallback& progress = {});
  RenderedFrame render(const Camera& camera, const FrameSettings& settings, bool aovs,
                       const ProgressCallback& progress = {});
  // The ground truth of `camera` by settings.renderer's visibility (render/
  // ground_truth_frame.h).
  GroundTruthBuffer ground_truth(const Camera& camera, const FrameSettings& settings,
                                 const GroundTruthTimes& times);

  // The scene's meshes `meshes` were posed again (Scene::pose: the same vertex and triangle
  // counts): each back end brings its compilation up to date before its next frame, rebuilding
  // only what changed where it can (trace/trace_scene.h), else compiling again.
  void scene_changed(std::span<const uint32_t> meshes);

  // How many times a back end compiled the scene, and brought a compilation up to date in place
  // (benchmarks and tests).
  int compilations() const { return compilations_; }
  int updates() const { return updates_; }

 private:
  struct Compiled;  // one back end's compilation, by its compiled form
  // A compilation of settings.renderer's back end serving `interval`: kept or made.
  const CompiledScene& compiled(Renderer renderer, const Shutter& interval);

  const Scene& scene_;
  std::vector<Compiled> compiled_;
  int compilations_ = 0, updates_ = 0;
};

}  // namespace obscura

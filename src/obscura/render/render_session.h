// A scene held for many frames: what a renderer compiles of it (the tracer's Embree scene, its
// lights and materials) is built once and kept while the frames it serves need nothing else —
// the frames of a sequence, the parts of a frame, a Python loop, later a live view. A scene whose
// objects do not move over the shutter compiles once for any exposure; one whose objects move is
// compiled again when a frame's exposure interval differs from the last one's.
#pragma once

#include <memory>

#include "obscura/render/render_frame.h"

namespace obscura {

class RenderSession {
 public:
  // `scene` must outlive the session and stay unchanged while it lives.
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

  // How many times the tracer's scene was compiled (benchmarks and tests).
  int tracer_compilations() const { return tracer_compilations_; }

 private:
  struct CompiledTracer;  // trace/'s scene and its device, with the interval it serves
  const Scene& scene_;
  std::unique_ptr<CompiledTracer> tracer_;
  int tracer_compilations_ = 0;
};

}  // namespace obscura

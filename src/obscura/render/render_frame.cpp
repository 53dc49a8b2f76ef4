#include "obscura/render/render_frame.h"

#include "obscura/render/render_session.h"

namespace obscura {

// A frame alone: a session that lives for one frame.
FrameStats render_frame(const Scene& scene, const Camera& camera, const FrameSettings& settings,
                        Film& film, AovBuffers* aovs, const ProgressCallback& progress) {
  return RenderSession(scene).render(camera, settings, film, aovs, progress);
}

RenderedFrame render_frame(const Scene& scene, const Camera& camera, const FrameSettings& settings,
                           bool aovs, const ProgressCallback& progress) {
  return RenderSession(scene).render(camera, settings, aovs, progress);
}

}  // namespace obscura

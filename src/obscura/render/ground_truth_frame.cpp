#include "obscura/render/ground_truth_frame.h"

#include "obscura/render/render_session.h"

namespace obscura {

GroundTruthBuffer render_ground_truth_frame(const Scene& scene, const Camera& camera,
                                            const FrameSettings& settings,
                                            const GroundTruthTimes& times) {
  return RenderSession(scene).ground_truth(camera, settings, times);
}

}  // namespace obscura

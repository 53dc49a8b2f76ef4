#include "obscura/render/renderer_backend.h"

#include <string>

#include "obscura/film/ground_truth_buffer.h"
#include "obscura/math/error.h"

namespace obscura {

void RendererBackend::check_ground_truth_camera(const Camera&) const {
  if (!capabilities_.ground_truth)
    throw Error("ground truth", std::string("the renderer '") + name_ + "' renders none");
}

GroundTruthBuffer RendererBackend::ground_truth(const CompiledScene&, const Camera&,
                                                const FrameSettings&,
                                                const GroundTruthTimes&) const {
  throw Error("ground truth", std::string("the renderer '") + name_ + "' renders none");
}

}  // namespace obscura

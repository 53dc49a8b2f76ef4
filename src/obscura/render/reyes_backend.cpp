// REYES's back end (reyes/render.h): micropolygons diced and shaded once per grid, sampled
// bucket by bucket with motion blur and depth of field in one pass. Its compiled scene keeps the
// scene's materials and lights; the meshes are diced per frame from the camera's view.
#include <memory>
#include <utility>

#include "obscura/render/backends.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/film/ground_truth_buffer.h"
#include "obscura/reyes/ground_truth.h"
#include "obscura/reyes/render.h"
#include "obscura/reyes/reyes_scene.h"

namespace obscura {

namespace {

class SceneToDice final : public CompiledScene {
 public:
  explicit SceneToDice(const Scene& scene) : reyes_(scene) {}
  // Dicing reads the scene's motion at each frame's exposure: any interval is served.
  bool serves(const Shutter&) const override { return true; }
  const reyes::ReyesScene& reyes() const { return reyes_; }

 private:
  reyes::ReyesScene reyes_;
};

class ReyesBackend final : public RendererBackend {
 public:
  ReyesBackend()
      : RendererBackend("reyes", "REYES micropolygons: motion blur and depth of field in one pass",
                        {.takes_samples_per_pixel = false,
                         .progress_unit = "frames",
                         .albedo = false,
                         .spectral = false,
                         .ground_truth = true,
                         .raster_settings = false,
                         .tile_size = reyes::kTileSize}) {}

  std::unique_ptr<CompiledScene> compile(const Scene& scene, const Shutter&) const override {
    return std::make_unique<SceneToDice>(scene);
  }

  FrameStats render(const CompiledScene& compiled, const Camera& camera,
                    const FrameSettings& settings, Film& film, AovBuffers* aovs,
                    const ProgressCallback& progress) const override {
    reyes::ReyesSettings reyes_settings = settings.reyes;
    reyes_settings.seed = settings.seed;
    reyes_settings.sampler = settings.sampler;
    reyes_settings.time_limit_s = settings.time_limit_s;
    reyes_settings.cancel = settings.cancel;
    reyes_settings.share = settings.share;
    reyes::ReyesStats stats = reyes::render(static_cast<const SceneToDice&>(compiled).reyes(),
                                            camera, reyes_settings, film, aovs, progress);
    FrameStats frame;
    frame.seconds = stats.seconds;
    frame.done = stats.cancelled ? 0 : 1;
    frame.requested = 1;
    frame.cancelled = stats.cancelled;
    frame.time_limited = stats.time_limited;
    frame.details = stats.lines();
    frame.warnings = std::move(stats.warnings);
    return frame;
  }

  void check_ground_truth_camera(const Camera& camera) const override {
    reyes::check_ground_truth_camera(camera);
  }

  // What REYES's hider sees at the pixel centres, made exact from the scene's triangles.
  GroundTruthBuffer ground_truth(const CompiledScene& compiled, const Camera& camera,
                                 const FrameSettings& settings,
                                 const GroundTruthTimes& times) const override {
    return reyes::render_ground_truth(static_cast<const SceneToDice&>(compiled).reyes(), camera,
                                      settings.reyes, times, settings.cancel);
  }
};

}  // namespace

const RendererBackend& reyes_backend() {
  static const ReyesBackend backend;
  return backend;
}

}  // namespace obscura

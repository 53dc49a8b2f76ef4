// The rasterizer's back end (raster/render.h). The rasterizer draws the scene as it is at each
// frame's moments; what it prepares of it (meshes in its vertex format, mipmapped textures, the
// environment's lighting) is kept for the session's next frames, one preparation per setting.
#include <memory>
#include <utility>

#include "obscura/film/ground_truth_buffer.h"
#include "obscura/raster/ground_truth_render.h"
#include "obscura/raster/rasterizer_cache.h"
#include "obscura/raster/render.h"
#include "obscura/raster/render_target.h"
#include "obscura/render/backends.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/scene/surface_motion.h"

namespace obscura {

namespace {

class SceneToRasterize final : public CompiledScene {
 public:
  explicit SceneToRasterize(const Scene& scene) : scene_(scene), prepared_(scene) {}
  // Motion is drawn from the scene at each frame's times: every exposure is served.
  bool serves(const Shutter&) const override { return true; }
  bool update(const Scene&, std::span<const uint32_t> changed, const Shutter&) override {
    prepared_.meshes_changed(changed);
    return true;
  }
  const Scene& scene() const { return scene_; }
  // Shared by the frames of the session, which the back end renders through a const reference.
  raster::RasterizerCache& prepared() const { return prepared_; }

 private:
  const Scene& scene_;
  mutable raster::RasterizerCache prepared_;
};

class RasterBackend final : public RendererBackend {
 public:
  RasterBackend()
      : RendererBackend("raster", "the software rasterizer",
                        {.takes_samples_per_pixel = false,
                         .progress_unit = "frames",
                         .albedo = false,
                         .spectral = false,
                         .ground_truth = true,
                         .raster_settings = true,
                         .tile_size = raster::kTileSize}) {}

  std::unique_ptr<CompiledScene> compile(const Scene& scene, const Shutter&) const override {
    return std::make_unique<SceneToRasterize>(scene);
  }

  FrameStats render(const CompiledScene& compiled, const Camera& camera,
                    const FrameSettings& settings, Film& film, AovBuffers* aovs,
                    const ProgressCallback& progress) const override {
    raster::RenderSettings raster_settings = settings.raster;
    raster_settings.seed = settings.seed;
    raster_settings.time_limit_s = settings.time_limit_s;
    raster_settings.cancel = settings.cancel;
    raster_settings.share = settings.share;
    const auto& scene = static_cast<const SceneToRasterize&>(compiled);
    raster::RenderStats stats = raster::render(scene.scene(), camera, raster_settings, film, aovs,
                                               progress, &scene.prepared());
    FrameStats frame;
    frame.seconds = stats.seconds;
    frame.done = stats.frames;
    frame.requested = stats.frames_requested;
    frame.cancelled = stats.cancelled;
    frame.time_limited = stats.time_limited;
    frame.warnings = std::move(stats.warnings);
    frame.post_dof = std::move(stats.post_dof);
    return frame;
  }

  void check_ground_truth_camera(const Camera& camera) const override {
    raster::check_ground_truth_camera(camera);
  }

  // Visibility at the pixel centre: no MSAA, and no shadows (shading plays no part).
  GroundTruthBuffer ground_truth(const CompiledScene& compiled, const Camera& camera,
                                 const FrameSettings& settings,
                                 const GroundTruthTimes& times) const override {
    const auto& scene = static_cast<const SceneToRasterize&>(compiled);
    raster::RasterSettings raster_settings = raster::rasterizer_settings(settings.raster, true);
    raster_settings.msaa_samples = 1;
    raster_settings.shadow_map_size = 0;
    const std::shared_ptr<const raster::SceneRasterizer> rasterizer =
        scene.prepared().get(raster_settings);
    return raster::render_ground_truth(*rasterizer, SurfaceMotion(scene.scene()), camera, times,
                                       settings.cancel);
  }
};

}  // namespace

const RendererBackend& rasterizer_backend() {
  static const RasterBackend backend;
  return backend;
}

}  // namespace obscura

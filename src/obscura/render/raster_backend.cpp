// The rasterizer's back end (raster/render.h). The rasterizer prepares what it draws (meshes in
// its bins, textures, shadow maps) for each frame from the scene and its own settings, so its
// compiled scene is the scene itself.
#include <memory>
#include <utility>

#include "obscura/film/ground_truth_buffer.h"
#include "obscura/raster/ground_truth_render.h"
#include "obscura/raster/render.h"
#include "obscura/raster/render_target.h"
#include "obscura/render/backends.h"
#include "obscura/render/renderer_backend.h"
#include "obscura/scene/surface_motion.h"

namespace obscura {

namespace {

class SceneToRasterize final : public CompiledScene {
 public:
  explicit SceneToRasterize(const Scene& scene) : scene_(scene) {}
  // The rasterizer reads the scene as it is at each frame: nothing to bring up to date.
  bool serves(const Shutter&) const override { return true; }
  bool update(const Scene&, std::span<const uint32_t>, const Shutter&) override { return true; }
  const Scene& scene() const { return scene_; }

 private:
  const Scene& scene_;
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
    raster::RenderStats stats =
        raster::render(static_cast<const SceneToRasterize&>(compiled).scene(), camera,
                       raster_settings, film, aovs, progress);
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
    const Scene& scene = static_cast<const SceneToRasterize&>(compiled).scene();
    raster::RasterSettings raster_settings = raster::rasterizer_settings(settings.raster, true);
    raster_settings.msaa_samples = 1;
    raster_settings.shadow_map_size = 0;
    const raster::SceneRasterizer rasterizer(scene, raster_settings);
    return raster::render_ground_truth(rasterizer, SurfaceMotion(scene), camera, times,
                                       settings.cancel);
  }
};

}  // namespace

const RendererBackend& rasterizer_backend() {
  static const RasterBackend backend;
  return backend;
}

}  // namespace obscura

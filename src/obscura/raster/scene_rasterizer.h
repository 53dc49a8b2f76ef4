// Draws a Scene through the rasterization pipeline with the scene's camera: the rasterizer's
// counterpart of the tracer's TraceScene + render().
//
// Compiled once from the authoring scene: one object-space vertex array per mesh, one
// SurfaceMaterial per material (textures as mipmapped raster textures), the lights (point, spot
// and directional as they are; every emissive instance also as a SurfaceLight, the area light
// seen as a point; the environment as image-based lighting (environment_lighting.h) and as the
// background). Directional and spot lights cast shadows through shadow maps rendered per frame;
// point and surface lights do not. Then any number of frames, each at one shutter time and
// optionally with the camera's matrices replaced (jittered lens positions for accumulated depth of
// field).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "obscura/camera/animated_transform.h"
#include "obscura/camera/camera.h"
#include "obscura/film/film.h"
#include "obscura/film/image.h"
#include "obscura/math/matrix4.h"
#include "obscura/raster/environment_lighting.h"
#include "obscura/raster/lights.h"
#include "obscura/raster/render_settings.h"
#include "obscura/raster/render_target.h"
#include "obscura/raster/shaders.h"
#include "obscura/raster/shadow_map.h"
#include "obscura/raster/surface_material.h"
#include "obscura/raster/texture.h"
#include "obscura/raster/tile_rasterizer.h"
#include "obscura/scene/scene.h"

namespace obscura::raster {

struct InstanceUniforms;  // scene_program.h

struct RasterSettings {
  int msaa_samples = 1;  // 1, 4 or 8
  ShadingMode shading = ShadingMode::kPhong;
  bool cull_back_faces = false;  // front faces wind counter-clockwise (the scene's convention)
  Wireframe wireframe;
  bool aovs = false;           // keep object ids, view depth and normals (make_target)
  bool surface_lights = true;  // emissive instances light the scene as SurfaceLights
  // Texels per side of each directional and spot light's shadow map; 0: no shadows.
  int shadow_map_size = 1024;

  bool operator==(const RasterSettings&) const = default;
};

// One frame's camera. Unset matrices come from the camera at `time_s`.
struct RasterFrame {
  double time_s = 0;  // instances' motion keys and the camera's animated transform are taken here
  std::optional<Matrix4> view;        // camera_from_world, replacing camera.view_matrix(time_s)
  std::optional<Matrix4> projection;  // clip_from_camera, replacing camera.projection_matrix()
};

class SceneRasterizer {
 public:
  // What no setting changes: the textures mipmapped, the materials reading them, the environment
  // as background and image-based lighting — the costly part of preparing a textured scene,
  // shared by rasterizers of one scene prepared with different settings.
  struct Surfaces {
    std::vector<Texture> textures;        // the used scene textures
    std::vector<Texture> alpha_textures;  // the alpha channels some material reads
    // Both by scene texture index, which `materials` point to.
    std::shared_ptr<const TextureTable> texture_table;
    std::vector<SurfaceMaterial> materials;
    // Background: an equirectangular radiance map (empty: constant) times a colour.
    Image environment_map;
    Rgb environment_scale;
    Transform environment_from_world;
    // Its image-based lighting, which the lights' environment points to.
    std::shared_ptr<const EnvironmentLighting> environment_lighting;
  };

  // Throws obscura::Error for an invalid scene or settings (MSAA not 1, 4 or 8). `share`: the
  // surfaces of another rasterizer of the same scene, taken instead of preparing them again.
  explicit SceneRasterizer(const Scene& scene, RasterSettings settings = {},
                           std::shared_ptr<const Surfaces> share = nullptr);

  const std::shared_ptr<const Surfaces>& surfaces() const { return surfaces_; }

  // A target covering the camera's crop window, with the settings' MSAA and AOVs.
  RenderTarget make_target(const Camera& camera) const;
  // Clears `target` (the background: the environment, or black) and draws every instance into
  // it: exposed linear radiance (× camera.exposure_scale()), ready for a film. The target must
  // have the crop window's size. Throws obscura::Error for cameras without a projection matrix
  // (spherical ones) unless `frame.projection` is given.
  void render_frame(const Camera& camera, const RasterFrame& frame, RenderTarget& target) const;
  // One frame in the middle of the shutter interval, added to `film` (the crop's size) with
  // weight 1; fills `target` if given (else a temporary one).
  void render(const Camera& camera, Film& film, RenderTarget* target = nullptr) const;

  // The scene's meshes `meshes` were posed again (Scene::pose: their vertex and triangle counts
  // kept): recompiles those meshes, the bounds shadow maps cover and the lights (an emissive
  // mesh's surface light moves with it), keeping the textures, materials and environment.
  void update_meshes(const Scene& scene, std::span<const uint32_t> meshes);

  const LightSet& lights() const { return lights_; }
  const RasterSettings& settings() const { return settings_; }
  // What compilation approximated or skipped, for the user.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  struct CompiledInstance {
    uint32_t mesh, material;
    Transform world_from_object;
    std::optional<AnimatedTransform> motion;
  };
  static std::shared_ptr<const Surfaces> prepare_surfaces(const Scene& scene);
  void gather_lights(const Scene& scene);               // lights_ from the scene
  static Bounds3f instance_bounds(const Scene& scene);  // every instance at every motion key
  Transform world_from_object(const CompiledInstance& instance, double time_s) const;
  // The mesh's vertices at `time_s`: compiled once, or, for a deforming mesh, posed into
  // `scratch` (vertices) and `scratch_indices`.
  std::pair<const std::vector<MeshVertex>*, const std::vector<uint32_t>*> mesh_at(
      uint32_t mesh, double time_s, std::vector<MeshVertex>& scratch,
      std::vector<uint32_t>& scratch_indices) const;
  void draw_background(const Matrix4& world_from_clip, RenderTarget& target, float exposure) const;
  ShadowMap render_shadow_map(const Matrix4& clip_from_world, float texel_world, bool perspective,
                              double time_s) const;
  // Draws instance i; `sorted`, where not empty, replaces the mesh's triangle order.
  void draw_instance(RenderTarget& target, const InstanceUniforms& base,
                     const Matrix4& clip_from_world, size_t i, double time_s,
                     std::span<const uint32_t> sorted = {}) const;
  // Draws the instances with alphaMode BLEND after everything else, back to front.
  void draw_blended(RenderTarget& target, const InstanceUniforms& base,
                    const Matrix4& clip_from_world, const Matrix4& camera_from_world,
                    const std::vector<size_t>& blended, double time_s) const;

  RasterSettings settings_;
  std::vector<std::vector<MeshVertex>> vertices_;  // per mesh, object space
  std::vector<std::vector<uint32_t>> indices_;     // per mesh (empty: unindexed)
  std::map<uint32_t, Mesh> deforming_;             // meshes posed per frame, by index
  std::vector<int> normal_map_uv_set_;             // per mesh: its normal map's UV set, or −1
  std::shared_ptr<const Surfaces> surfaces_;       // shared by the scene's rasterizers
  std::vector<CompiledInstance> instances_;
  LightSet lights_;
  Bounds3f bounds_;  // every instance at every motion key (what shadow maps must cover)
  std::vector<std::string> warnings_;
};

// The outputs the tracer also writes (its AOVs), from a target rendered with aovs on:
// the instance index per pixel (−1 for the background), as float;
Image id_image(const RenderTarget& target);
// the depth along the camera's optical axis (camera-space −z, m; +∞ for the background), one
// channel "Z" (the view depth);
Image depth_image(const RenderTarget& target);
// the distance from the camera along the pixel centre's ray (m; +∞ for the background), one
// channel "range", from the view depth (perspective: scaled by the ray's length per unit depth);
Image range_image(const RenderTarget& target, const Camera& camera);
// the world-space shading normal facing the camera.
Image normal_image(const RenderTarget& target);

}  // namespace obscura::raster

// The scene: plain authoring data that both renderers read and compile into their own forms
// (the tracer into Embree geometry, the rasterizer into vertex arrays). Loaders in io/ fill it;
// nothing in it knows about files or renderers.
//
// Meshes live in object space and are placed by instances. Materials, textures, lights and
// cameras are referred to by index. Units: metres, seconds, linear Rec.709 RGB.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/math/bounds.h"
#include "obscura/scene/instance.h"
#include "obscura/scene/light.h"
#include "obscura/scene/material.h"
#include "obscura/scene/mesh.h"
#include "obscura/scene/mesh_poser.h"
#include "obscura/scene/reyes_knobs.h"
#include "obscura/scene/texture.h"

namespace obscura {

// The most samples per pixel a scene file or the command line may ask for (2^20).
inline constexpr int kMaxSamplesPerPixel = 1 << 20;

// Render settings a scene file may suggest; the command line overrides them.
struct SceneRenderSettings {
  std::optional<int> width, height;  // pixels
  std::optional<int> samples_per_pixel;
  std::optional<uint64_t> seed;
  std::optional<bool> spectral;  // spectral light transport (path tracer)
  // Diffraction glare (render/camera_glare.h): its strength (1 = the aperture's own) and radius.
  std::optional<double> glare_strength;
  std::optional<int> glare_radius_px;
  // Ghost flares of a lens-system camera (render/lens_flare.h).
  std::optional<bool> flare;
  // REYES's knobs (the `render.reyes` block).
  SceneReyesSettings reyes;
};

// Counts for `obscura info` and benchmarks.
struct SceneStats {
  size_t triangles = 0;         // as rendered: every instance counts its mesh's triangles
  size_t unique_triangles = 0;  // stored: each mesh counted once
  size_t vertices = 0;          // stored
  size_t meshes = 0, instances = 0, materials = 0, textures = 0;
  size_t lights = 0;           // point, spot and directional lights
  size_t emissive_meshes = 0;  // instances whose material emits (area lights)
  size_t cameras = 0;
  size_t memory_bytes = 0;  // heap bytes of meshes and textures
};

struct Scene {
  std::string name;
  std::vector<Mesh> meshes;         // object space
  std::vector<Instance> instances;  // what is rendered: meshes without an instance are not
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Light> lights;
  std::optional<Environment> environment;
  std::vector<Camera> cameras;  // every camera the file names (Camera::name), in file order
  Camera camera;                // the camera to render with (by default cameras.front())
  SceneRenderSettings render;
  // KHR_materials_variants: the names of the file's material variants (Instance says which
  // material each uses); the materials rendered until one is selected are the file's defaults.
  std::vector<std::string> material_variants;
  std::vector<std::string> warnings;  // what the loader skipped or approximated, for the user
  // Every file the scene was read from (scene, models, buffers, textures, environment map), so
  // that a command can refuse to write its output over one of them.
  std::vector<std::string> input_files;
  // What poses the meshes that change shape with time (skins, morph targets), where the file has
  // such; shared by copies of the scene, never changed.
  std::shared_ptr<const MeshPoser> poser;

  // The material an instance is drawn with: its override, else its mesh's.
  uint32_t material_of(const Instance& instance) const {
    return instance.material >= 0 ? uint32_t(instance.material) : meshes[instance.mesh].material;
  }
  // Adds `mesh` with one instance at `world_from_object`; returns the mesh index.
  uint32_t add_mesh(Mesh mesh, const Transform& world_from_object = {});
  // Adds each mesh with one instance in place (world space = object space).
  void add_meshes(std::vector<Mesh> meshes);

  // Poses the meshes that change shape with time at `time_s`, across a shutter of `exposure_s`
  // around it (scene/mesh_poser.h); returns their indices: none for a scene without a poser.
  std::vector<uint32_t> pose(double time_s, double exposure_s);

  SceneStats stats() const;
  size_t triangle_count() const { return stats().triangles; }
  // World-space bounds of all instances at their time-0 pose.
  Bounds3f bounds() const;
  // Throws obscura::Error naming the first mesh, index, attribute, reference or value that is
  // invalid (indices past the vertex count, NaN positions, dangling material or texture indices).
  void validate() const;
};

}  // namespace obscura

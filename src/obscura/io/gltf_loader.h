// glTF 2.0 (.gltf with its buffers and images, or .glb) into a Scene, via tinygltf.
//
// Read: triangle primitives (strips and fans converted; points and lines skipped with a warning)
// with POSITION, NORMAL, TEXCOORD_0, TANGENT, COLOR_0; the default scene's node hierarchy,
// flattened into instances (meshes shared, not copied); metallic-roughness materials and their
// textures and samplers; KHR_materials_emissive_strength, KHR_materials_specular,
// KHR_materials_ior; KHR_materials_unlit, _transmission, _volume and _variants
// (gltf_material_extensions.h); KHR_lights_punctual; KHR_mesh_quantization;
// KHR_draco_mesh_compression and EXT_meshopt_compression (gltf_draco.h, gltf_meshopt.h);
// EXT_mesh_gpu_instancing (one instance per copy); perspective and orthographic cameras; one
// animation's (GltfLoadOptions::animation, else the first) node translation/rotation/scale
// channels, as instance keyframes for motion blur; skins and morph targets (with 'weights'
// channels), posed once at GltfLoadOptions::time_s (gltf_deformation.h). Any one of the file's
// scenes (GltfLoadOptions::scene). KHR_materials_clearcoat and _sheen.
//
// Hostile files are expected: every accessor is checked against its buffer before anything is
// allocated (gltf_accessor.h), what a file decodes to is bounded, the spec's structural rules are
// enforced (gltf_validation.h), and files are read only when regular and at most
// kMaxGltfFileBytes. An image that cannot be read is a warning (gltf_missing_image.h): looked for
// next to the model under its base name, else a visible checker for base colour and the factors
// alone for other textures.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "obscura/scene/scene.h"

namespace obscura {

// The largest .gltf, .glb or external buffer/image file read (1 GiB; GLB itself caps at 4 GiB).
inline constexpr uint64_t kMaxGltfFileBytes = uint64_t(1) << 30;

struct GltfLoadOptions {
  // The scene to show: its index ("1") or name; empty: the file's `scene`, else the first.
  std::string scene;
  // The animation that plays: its index ("2") or name; empty: the first.
  std::string animation;
  // When skins and morph targets are posed (seconds on the animation's clock); rigid node
  // animation is kept whole as keyframes for the renderers to sample over the shutter.
  double time_s = 0;
  // The shutter's length around time_s: animated skins and morphs are also posed across it
  // (Mesh::deformation) so that they motion-blur; 0 poses them once.
  double exposure_s = 0;
};

// Throws obscura::Error naming the file and the glTF element (e.g. "meshes[2].primitives[0]")
// for anything malformed: truncated files, indices or accessors out of range, NaN positions,
// an unsupported version or required extension, a node hierarchy with a cycle.
Scene load_gltf(const std::string& path, const GltfLoadOptions& options = {});

// The same from bytes already in memory (binary glTF when they start with "glTF", JSON
// otherwise); `name` prefixes messages, relative URIs resolve against `base_dir`.
Scene load_gltf_bytes(std::span<const uint8_t> bytes, const std::string& name,
                      const std::string& base_dir, const GltfLoadOptions& options = {});

// A whole file, if it is a regular file of at most kMaxGltfFileBytes; else obscura::Error.
std::vector<unsigned char> read_gltf_file(const std::string& path);

}  // namespace obscura

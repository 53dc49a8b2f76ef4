// What poses a scene's deforming meshes at any moment: a glTF file's skins and morph targets
// (io/gltf_mesh_poser.h), kept with the scene it was read into so that the frames of a sequence,
// a Python loop or a live view pose the scene again instead of reading the file again.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace obscura {

struct Mesh;

class MeshPoser {
 public:
  virtual ~MeshPoser() = default;
  // The meshes it poses, as indices into Scene::meshes.
  virtual std::span<const uint32_t> meshes() const = 0;
  // Poses them at `time_s` (seconds on the animation's clock) and, with `exposure_s` > 0, across
  // the shutter [time_s − exposure_s/2, time_s + exposure_s/2] for motion blur (Mesh::
  // deformation): exactly as the file would have been read at that moment. Thread-safe.
  // Throws obscura::Error if `meshes` no longer holds them.
  virtual void pose(std::vector<Mesh>& meshes, double time_s, double exposure_s) const = 0;
};

}  // namespace obscura

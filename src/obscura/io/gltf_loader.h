// glTF 2.0 (.gltf with its buffers and images, or .glb) into a Scene, via tinygltf.
//
// Read: triangle primitives (strips and fans converted; points and lines skipped with a warning)
// with POSITION, NORMAL, TEXCOORD_0, TANGENT, COLOR_0; the default scene's node hierarchy,
// flattened into instances (meshes shared, not copied); metallic-roughness materials and their
// textures and samplers; KHR_materials_emissive_strength, KHR_materials_specular,
// KHR_materials_ior; KHR_lights_punctual; perspective and orthographic cameras; the first
// animation's node translation/rotation/scale channels, as instance keyframes for motion blur.
#pragma once

#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

// Throws obscura::Error naming the file and the glTF element (e.g. "meshes[2].primitives[0]")
// for anything malformed: truncated files, indices or accessors out of range, NaN positions,
// missing images.
Scene load_gltf(const std::string& path);

}  // namespace obscura

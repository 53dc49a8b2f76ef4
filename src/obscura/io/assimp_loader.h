// FBX, COLLADA, 3DS… (every format Assimp reads) into a Scene. OBJ, PLY and STL files go to
// Obscura's own readers (obj_loader.h, ply_loader.h, stl_loader.h) instead, which produce the
// same layout; this loader still reads them when called directly (the parity tests compare).
//
// Faces are triangulated, points and lines dropped; texture coordinates are flipped to glTF's
// convention (v = 0 at the image's top). OBJ/MTL materials become Phong materials: Ka, Kd, Ks,
// Ns, map_Kd, and Ke as emission. Formats without materials get a grey diffuse one. The node
// hierarchy is flattened into instances; no units or up-axis conversion is applied here (the
// JSON scene file's model transform does that explicitly).
#pragma once

#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

// Throws obscura::Error naming the file (and, where Assimp says, the line) when it is missing
// or malformed, when a face refers past the vertex count, or a texture does not exist.
Scene load_with_assimp(const std::string& path);

}  // namespace obscura

// STL (ASCII and binary) into a Scene: one mesh per solid, its facet normals as per-vertex
// normals (vertices shared where position and normal agree), and the white Phong material Assimp
// gave STL files (Ka 0.05, Kd 1, Ks 1), so that scenes look as they did before this loader.
//
// Binary or ASCII is decided by content, not by the first word: binary files may start with
// "solid" too. A file is binary when its size is exactly 84 + 50 × the triangle count in its
// header, or when it is not text; a binary file shorter than its count needs is refused before
// anything is allocated. A zero or non-finite facet normal is replaced by the triangle's own.
#pragma once

#include <span>
#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

// Throws obscura::Error naming the file (and the line or triangle) when it is missing, not a
// regular file, truncated or malformed, or a position is not finite.
Scene load_stl(const std::string& path);

// The same from bytes in memory; `name` names the file in messages and the scene.
Scene load_stl_bytes(std::span<const char> bytes, const std::string& name);

}  // namespace obscura

// PLY (ascii, binary_little_endian, binary_big_endian) into a Scene with one mesh, as Assimp
// gave it: the "vertex" element's x y z, nx ny nz, texture coordinates (u v, s t, texture_u
// texture_v or texture_s texture_t; flipped to glTF's v = 0 at the top) and red green blue
// (integer types scaled to [0, 1], float types as they are); the "face" element's vertex_indices
// (or vertex_index) lists of any count and index type, fan-triangulated, lists of fewer than
// three dropped. Vertices no face uses are dropped. The material is Assimp's white Phong
// ("material 0": Ka, Kd and Ks 1). Other elements and properties are skipped (tristrips with a
// warning: they are not read).
//
// Every element count is checked against the file's size before anything is allocated
// (ply_header.h); a file that ends early, a malformed value, an index past the vertex count or
// a non-finite position is an obscura::Error naming the file, the element and entry, and for
// ASCII files the line.
#pragma once

#include <span>
#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

Scene load_ply(const std::string& path);

// The same from bytes in memory; `name` names the file in messages and the scene.
Scene load_ply_bytes(std::span<const char> bytes, const std::string& name);

}  // namespace obscura

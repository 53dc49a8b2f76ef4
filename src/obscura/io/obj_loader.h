// Wavefront OBJ (with its MTL libraries) into a Scene, laid out as Assimp laid it out, so that
// scenes and tests written against the Assimp path see the same meshes, names and materials:
//
// - "o" and "g" start an object (a "g" repeating the current name does not); faces before any
//   start one named "defaultobject". Each object has one mesh per material, in order of use: its
//   first mesh takes the object's name, later ones (after a "usemtl" that follows faces) the
//   material's. Every non-empty mesh gets one instance, named after its object, in place.
// - Faces are fan-triangulated; points ("p") and lines ("l", and faces of fewer than three
//   corners) are dropped. Indices may be negative (relative to the end). Each distinct
//   v/vt/vn combination a mesh uses becomes one vertex, in order of first use.
// - "v x y z r g b" gives vertex colours. Texture coordinates are flipped (v' = 1 − v) to glTF's
//   convention. A mesh where only some corners have vt gets (0, 1), as Assimp gave, for the
//   others; normals are normalised, and a corner without one (or with a zero one) gets the
//   average of its faces' normals instead of Assimp's zero vector.
// - Materials: MTL Ka, Kd, Ks, Ns, map_Kd as Phong, Ke and map_Ke as emission (mtl_reader.h).
//   Faces without "usemtl" use "DefaultMaterial" (Kd 0.6); a "usemtl" naming no known material
//   gets a material of that name with the defaults, and a warning; a missing "mtllib" file is
//   one warning. Only the materials some mesh uses are kept, in library order.
#pragma once

#include <span>
#include <string>

#include "obscura/scene/scene.h"

namespace obscura {

// Throws obscura::Error naming the file and line for malformed statements, an index of 0 or
// outside the vertices defined so far, a non-finite number, or a texture that does not exist.
Scene load_obj(const std::string& path);

// The same from bytes in memory: `name` names the file in messages and the scene; "mtllib" and
// texture paths resolve against `base_dir`.
Scene load_obj_bytes(std::span<const char> bytes, const std::string& name,
                     const std::string& base_dir);

}  // namespace obscura

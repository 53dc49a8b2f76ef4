// Per-vertex tangents for normal mapping, generated from a mesh's texture coordinates where the
// file gave none (glTF asks for MikkTSpace tangents then).
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/math/vector.h"
#include "obscura/scene/mesh.h"

namespace obscura {

// One tangent per vertex in glTF's convention: xyz is the unit direction of increasing u, w = ±1
// such that the bitangent w · cross(N, T) points along decreasing v (up in the image, as a
// normal map's +Y), so a mirrored UV layout gets w = −1. Built from UV set `uv_set`; empty when
// the mesh has no such set.
//
// Equivalent to MikkTSpace in what it is meant to give: per-triangle tangents from the UV
// derivatives, projected into each vertex's normal plane, normalized and weighted by the corner
// angle, summed per vertex, orthogonalised against the vertex normal (Gram–Schmidt), with the
// handedness of the UV layout in w. Not equivalent: MikkTSpace splits a vertex shared by
// triangles of opposite handedness (a mirror seam with welded UVs) or of very different tangents
// into several; this keeps one vertex and takes the handedness the larger corner angles agree
// on, so such a seam can differ from a MikkTSpace bake along its one-triangle-wide border. Meshes
// exported with split UV seams (the usual case) match. Triangles whose UVs are degenerate add
// nothing; a vertex with no usable triangle gets an arbitrary tangent perpendicular to its normal.
// Meshes without normals use each triangle's own normal (the tracer and the rasterizer shade
// them flat).
std::vector<Vector4f> generate_tangents(const Mesh& mesh, uint32_t uv_set);

}  // namespace obscura

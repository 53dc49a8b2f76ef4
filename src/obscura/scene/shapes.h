// Meshes generated in code for the JSON scene file's shapes and for tests: a UV sphere, a
// rectangle, a box. All are centred on the origin, with outward normals and UVs.
#pragma once

#include "obscura/scene/mesh.h"

namespace obscura {

// `segments` around the equator (≥ 3), half as many rings from pole to pole.
Mesh make_sphere(float radius, int segments);
// The same tessellation of a sphere of `radius` that also keeps the sphere itself
// (Mesh::analytic_sphere), for renderers that draw it exactly.
Mesh make_analytic_sphere(float radius, int segments);
// A width × depth rectangle in the XZ plane, facing +Y.
Mesh make_rectangle(float width, float depth);
// An axis-aligned box with the given edge lengths; each face has its own vertices.
Mesh make_box(Vector3f size);

}  // namespace obscura

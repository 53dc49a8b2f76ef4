// A triangle mesh in its own object space: what an Instance places in the world.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/math/bounds.h"
#include "obscura/math/vector.h"

namespace obscura {

// A mesh that changes shape while the shutter is open (a glTF skin or morph animation): its
// vertices at evenly spaced times from `open_s` to `close_s`, linearly interpolated between and
// held outside. Renderers blur it as they blur moving instances.
struct MeshDeformation {
  double open_s = 0, close_s = 0;
  std::vector<std::vector<Point3f>> positions;  // per time step: one per vertex
  std::vector<std::vector<Normal3f>> normals;   // per time step: one per vertex, or none at all
};

// A sphere kept as its centre and radius (object space): the surface a mesh's triangles
// tessellate when it was made from one (the scene file's `analytic_sphere` shape). REYES dices
// it natively; the tracer and the rasterizer draw the triangles.
struct AnalyticSphere {
  Point3f center;
  float radius = 1;  // > 0
};

// Indexed triangles. Front faces wind counter-clockwise seen from outside: the geometric normal
// is (p1 − p0) × (p2 − p0). Every per-vertex array is either empty (absent) or has exactly one
// entry per position.
struct Mesh {
  std::string name;
  std::vector<Point3f> positions;
  std::vector<Normal3f> normals;   // unit shading normals
  std::vector<Point2f> uvs;        // texture coordinates; (0, 0) is the image's top-left (glTF)
  std::vector<Point2f> uvs1;       // a second set (glTF TEXCOORD_1), as uvs
  std::vector<Vector4f> tangents;  // xyz unit tangent along +u, w = ±1 bitangent sign (glTF)
  std::vector<Rgb> colors;         // linear vertex colours, multiplied into the base colour
  // The alpha of 4-component vertex colours (glTF COLOR_0): it multiplies the material's alpha
  // coverage. Kept apart from `colors` so that the many users of RGB colours stay as they are.
  std::vector<float> color_alphas;
  std::vector<uint32_t> indices;  // three per triangle
  uint32_t material = 0;          // index into Scene::materials; an Instance may override it
  MeshDeformation deformation;    // empty for a rigid mesh; `positions` is then the still pose
  // The analytic surface the triangles tessellate, if any (ignored while the mesh deforms).
  std::optional<AnalyticSphere> analytic_sphere;

  bool deforms() const { return deformation.positions.size() > 1; }
  // The mesh with its deformation's positions and normals at `time_s` (itself if rigid).
  Mesh posed_at(double time_s) const;

  // TextureRef::uv_set → coordinates: set 0 is `uvs`, set 1 `uvs1`; sets beyond are not kept
  // (empty).
  static constexpr uint32_t kUvSets = 2;
  const std::vector<Point2f>& uv_set(uint32_t set) const;

  size_t triangle_count() const { return indices.size() / 3; }
  size_t vertex_count() const { return positions.size(); }
  Bounds3f bounds() const;
  // Heap bytes held by the arrays (capacity, not size).
  size_t memory_bytes() const;
};

}  // namespace obscura

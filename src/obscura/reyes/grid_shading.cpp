// Dicing a block into a grid and shading its vertices: the material read at each vertex through
// the scene's full-resolution textures, lit as the rasterizer's per-pixel program lights a
// fragment (raster/scene_program.h) — the same formulas from shading/, evaluated once per grid
// vertex instead of once per pixel, and never again for another time or lens point.
#include <algorithm>
#include <cmath>

#include "obscura/math/shading_normal.h"
#include "obscura/reyes/grid.h"
#include "obscura/reyes/reyes_scene.h"
#include "obscura/reyes/vertex_shading.h"
#include "obscura/shading/material_point.h"
#include "obscura/shading/normal_map.h"
#include "obscura/shading/surface_response.h"

namespace obscura::reyes {

namespace {

// The scene's textures at one grid vertex (shading::TextureLookup), read as the tracer reads
// them at a hit: full resolution, bilinear.
struct VertexTextures {
  const std::vector<Texture>* textures;
  Point2f uv[Mesh::kUvSets];

  Rgb color(const TextureRef& t) const {
    if (!t.valid()) return Rgb(1.f);
    const Vector4f v = read(t);
    return {v.x, v.y, v.z};
  }
  float alpha(const TextureRef& t) const { return t.valid() ? read(t).w : 1.f; }

 private:
  Vector4f read(const TextureRef& t) const {
    const Point2f at = t.uv_set < Mesh::kUvSets ? uv[t.uv_set] : Point2f(0, 0);
    return sample_texture((*textures)[size_t(t.texture)], t.transform(at));
  }
};

Vector3f to_float(Vector3d v) {
  return {float(v.x), float(v.y), float(v.z)};
}

Vector3f unit(Vector3f v) {
  const float l2 = dot(v, v);
  return l2 > 0 ? v / std::sqrt(l2) : v;
}

Vector3f face_towards(Vector3f n, Vector3f v) {
  return dot(n, v) < 0 ? -n : n;
}

// The light a point reflects towards v: the uniform surround, then every light in the order the
// rasterizer adds them; light from behind the true surface (`geometric`) is blocked.
Rgb reflected_light(const shading::SurfacePoint& s, const shading::PunctualLights& lights,
                    Point3f p, Vector3f n, Vector3f geometric, Vector3f v) {
  Rgb sum = shading::ambient_reflectance(s, dot(n, v)) * lights.ambient;
  auto add = [&](const shading::IncidentLight& in) {
    if (dot(geometric, in.to_light) <= 0) return;
    sum += in.strength * shading::reflected_cosine(s, n, v, in.to_light);
  };
  for (const auto& l : lights.directional) add(shading::incident(l, p));
  for (const auto& l : lights.point) add(shading::incident(l, p));
  for (const auto& l : lights.spot) add(shading::incident(l, p));
  for (const auto& l : lights.surface) add(shading::incident(l, p));
  return sum;
}

template <class T>
T blend3(const std::vector<T>& values, const uint32_t idx[3], const double b[3]) {
  return values[idx[0]] * float(b[0]) + values[idx[1]] * float(b[1]) + values[idx[2]] * float(b[2]);
}

Normal3f blend_normals(const std::vector<Normal3f>& n, const uint32_t idx[3], const double b[3]) {
  const Normal3f &a = n[idx[0]], &c = n[idx[1]], &d = n[idx[2]];
  return {float(b[0] * a.x + b[1] * c.x + b[2] * d.x), float(b[0] * a.y + b[1] * c.y + b[2] * d.y),
          float(b[0] * a.z + b[1] * c.z + b[2] * d.z)};
}

}  // namespace

size_t Grid::bytes() const {
  return sizeof(Grid) + open.capacity() * sizeof(Point3d) + close.capacity() * sizeof(Point3d) +
         raster.capacity() * sizeof(Point2d) + color.capacity() * sizeof(Rgb) +
         alpha.capacity() * sizeof(float) + normal.capacity() * sizeof(Vector3f);
}

void GridCounts::add(const GridCounts& o) {
  grids += o.grids;
  micropolygons += o.micropolygons;
  shaded_vertices += o.shaded_vertices;
  displacement_overruns += o.displacement_overruns;
  measured += o.measured;
  area_min = std::min(area_min, o.area_min);
  area_max = std::max(area_max, o.area_max);
  area_sum += o.area_sum;
}

Grid start_grid(const Block& block, uint64_t key, uint32_t instance, uint32_t triangle,
                const shading::SurfaceMaterial& m, bool moves) {
  Grid g;
  g.key = key;
  g.nu = block.i1 - block.i0;
  g.nv = block.j1 - block.j0;
  g.mesh = instance;  // what the tracer's and the rasterizer's id AOVs hold
  g.instance = instance;
  g.triangle = triangle;
  if (m.alpha_mode == AlphaMode::kMask) g.coverage = Coverage::kMask;
  if (m.alpha_mode == AlphaMode::kBlend) g.coverage = Coverage::kBlend;
  g.alpha_cutoff = m.alpha_cutoff;
  const size_t n = g.vertices();
  g.open.reserve(n);
  if (moves) g.close.reserve(n);
  g.color.reserve(n);
  g.normal.reserve(n);
  if (g.coverage != Coverage::kOpaque) g.alpha.reserve(n);
  return g;
}

void shade_vertex(const ReyesScene& scene, const FrameView& view, const shading::SurfaceMaterial& m,
                  const VertexSurface& s, Grid& g) {
  const Point3d pd = s.position;
  const Point3f p(float(pd.x), float(pd.y), float(pd.z));
  const Vector3f v =
      view.perspective() ? unit(to_float(view.eye() - pd)) : to_float(view.to_viewer());
  VertexTextures lookup{&scene.scene().textures, {}};
  for (uint32_t set = 0; set < Mesh::kUvSets; ++set) lookup.uv[set] = s.uv[set];
  // As the rasterizer's per-pixel program: the true surface facing the viewer, the shading
  // normal (normal-mapped) kept visible from it.
  const Vector3f geometric = face_towards(s.true_normal, v);
  Vector3f shading_normal = s.shading_normal;
  if (m.normal_texture.valid() && s.tangent) {
    const Vector3f side = dot(shading_normal, geometric) < 0 ? -geometric : geometric;
    shading_normal =
        shading::keep_above_surface(shading::normal_mapped(m.normal_texture, m.normal_scale,
                                                           shading_normal, *s.tangent, lookup),
                                    side);
  }
  const Vector3f n = visible_shading_normal(shading_normal, geometric, v);
  shading::SurfacePoint sp = shading::surface_point_with(m, s.color, lookup);
  sp.coat_normal = m.model == shading::SurfaceModel::kLayeredMetallicRoughness
                       ? visible_shading_normal(s.shading_normal, geometric, v)
                       : geometric;
  Rgb c = sp.model == shading::SurfaceModel::kUnlit
              ? sp.base
              : reflected_light(sp, scene.lights(), p, n, geometric, v);
  if (dot(s.true_normal, v) > 0) c += shading::textured(m.emission, m.emission_texture, lookup);
  g.color.push_back(c);
  g.normal.push_back(face_towards(s.shading_normal, v));
  if (g.coverage != Coverage::kOpaque)
    g.alpha.push_back(m.base_alpha * s.alpha * lookup.alpha(m.alpha_texture));
}

void finish_grid(const FrameView& view, Grid& g, GridCounts& counts) {
  // Statistics (the micropolygons as diced: at the shading time, through the lens centre), and
  // the still frame's projection done once per grid.
  const size_t n = g.vertices();
  std::vector<Point2d> projected(n);
  const double f = view.motion_fraction(view.shading_time_s());
  for (size_t k = 0; k < n; ++k)
    projected[k] =
        view.project(g.close.empty() ? g.open[k] : g.open[k] + (g.close[k] - g.open[k]) * f);
  if (!view.moves() && !view.defocused()) g.raster = projected;
  GridCounts c;
  c.grids = 1;
  c.micropolygons = uint64_t(g.nu) * uint64_t(g.nv);
  c.shaded_vertices = n;
  const int row = g.row();
  for (int j = 0; j < g.nv; ++j)
    for (int i = 0; i < g.nu; ++i) {
      const Point2d a = projected[size_t(j) * row + i], bq = projected[size_t(j) * row + i + 1],
                    cq = projected[size_t(j + 1) * row + i + 1],
                    d = projected[size_t(j + 1) * row + i];
      // The quad's area from its diagonals.
      const double area = 0.5 * std::abs((cq.x - a.x) * (d.y - bq.y) - (cq.y - a.y) * (d.x - bq.x));
      if (!(area > 1e-9)) continue;
      ++c.measured;
      c.area_min = std::min(c.area_min, area);
      c.area_max = std::max(c.area_max, area);
      c.area_sum += area;
    }
  counts.add(c);
}

Grid dice_and_shade(const ReyesScene& scene, const FrameView& view, const DicePlan& plan,
                    const Block& block, uint64_t key, GridCounts& counts) {
  const Scene& s = scene.scene();
  const uint32_t instance = plan.piece.instance, triangle = plan.piece.triangle;
  const Instance& inst = s.instances[instance];
  const Mesh& mesh = s.meshes[inst.mesh];
  const uint32_t idx[3] = {mesh.indices[3 * size_t(triangle)],
                           mesh.indices[3 * size_t(triangle) + 1],
                           mesh.indices[3 * size_t(triangle) + 2]};
  const double ts = view.shading_time_s();
  const std::array<Point3d, 3> world = scene.motion().world_triangle(instance, triangle, ts);
  const Vector3f true_normal = to_float(scene.motion().geometric_normal(instance, triangle, ts));
  const Transform world_from_object = scene.motion().world_from_object(instance, ts);
  const float handedness = world_from_object.swaps_handedness() ? -1.f : 1.f;
  const shading::SurfaceMaterial& m = scene.material(s.material_of(inst));
  Grid g = start_grid(block, key, instance, triangle, m, view.moves());
  const bool has_tangents = !mesh.tangents.empty();

  for (int j = block.j0; j <= block.j1; ++j)
    for (int i = block.i0; i <= block.i1; ++i) {
      const LatticePoint lp = lattice_point(plan, i, j);
      g.open.push_back(lp.open);
      if (view.moves()) g.close.push_back(lp.close);
      const double b[3] = {1 - lp.bary.x - lp.bary.y, lp.bary.x, lp.bary.y};
      VertexSurface vs;
      vs.position = Point3d(b[0] * world[0].x + b[1] * world[1].x + b[2] * world[2].x,
                            b[0] * world[0].y + b[1] * world[1].y + b[2] * world[2].y,
                            b[0] * world[0].z + b[1] * world[1].z + b[2] * world[2].z);
      vs.true_normal = true_normal;
      vs.shading_normal = true_normal;
      if (!mesh.normals.empty()) {
        const Normal3f nw = world_from_object(blend_normals(mesh.normals, idx, b));
        vs.shading_normal = unit(Vector3f(nw.x, nw.y, nw.z));
      }
      for (uint32_t set = 0; set < Mesh::kUvSets; ++set) {
        const std::vector<Point2f>& uvs = mesh.uv_set(set);
        if (uvs.empty()) continue;
        vs.uv[set] =
            Point2f(float(b[0] * uvs[idx[0]].x + b[1] * uvs[idx[1]].x + b[2] * uvs[idx[2]].x),
                    float(b[0] * uvs[idx[0]].y + b[1] * uvs[idx[1]].y + b[2] * uvs[idx[2]].y));
      }
      if (!mesh.colors.empty()) vs.color = blend3(mesh.colors, idx, b);
      if (!mesh.color_alphas.empty())
        vs.alpha = float(b[0] * mesh.color_alphas[idx[0]] + b[1] * mesh.color_alphas[idx[1]] +
                         b[2] * mesh.color_alphas[idx[2]]);
      if (has_tangents) {
        const Vector4f t = blend3(mesh.tangents, idx, b);
        const Vector3f tw = world_from_object(Vector3f(t.x, t.y, t.z));
        const float w = (mesh.tangents[idx[0]].w < 0 ? -1.f : 1.f) * handedness;
        vs.tangent = Vector4f(tw.x, tw.y, tw.z, w);
      }
      shade_vertex(scene, view, m, vs, g);
    }
  finish_grid(view, g, counts);
  return g;
}

}  // namespace obscura::reyes

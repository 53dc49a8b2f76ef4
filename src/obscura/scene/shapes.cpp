#include "obscura/scene/shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace obscura {

Mesh make_sphere(float radius, int segments) {
  segments = std::max(segments, 3);
  int rings = std::max(segments / 2, 2);
  Mesh m;
  m.name = "sphere";
  const float pi = std::numbers::pi_v<float>;
  // Vertices on a (segments + 1) × (rings + 1) grid: the seam column is duplicated for UVs.
  for (int r = 0; r <= rings; ++r) {
    float theta = pi * r / rings;  // from the +Y pole
    for (int s = 0; s <= segments; ++s) {
      float phi = 2 * pi * s / segments;
      Vector3f n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      m.positions.push_back(Point3f(0, 0, 0) + n * radius);
      m.normals.emplace_back(n);
      m.uvs.emplace_back(float(s) / segments, float(r) / rings);
    }
  }
  auto vertex = [&](int r, int s) { return uint32_t(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      uint32_t a = vertex(r, s), b = vertex(r + 1, s), c = vertex(r + 1, s + 1),
               d = vertex(r, s + 1);
      // Counter-clockwise seen from outside; the pole rows lose their degenerate triangle.
      if (r != 0) m.indices.insert(m.indices.end(), {a, b, d});
      if (r != rings - 1) m.indices.insert(m.indices.end(), {d, b, c});
    }
  return m;
}

Mesh make_analytic_sphere(float radius, int segments) {
  Mesh m = make_sphere(radius, segments);
  m.name = "analytic sphere";
  m.analytic_sphere = AnalyticSphere{.center = {0, 0, 0}, .radius = radius};
  return m;
}

Mesh make_rectangle(float width, float depth) {
  Mesh m;
  m.name = "rectangle";
  float x = width / 2, z = depth / 2;
  m.positions = {{-x, 0, -z}, {-x, 0, z}, {x, 0, z}, {x, 0, -z}};
  m.normals.assign(4, Normal3f(0, 1, 0));
  m.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

Mesh make_box(Vector3f size) {
  Mesh m;
  m.name = "box";
  Vector3f h = size / 2.f;
  // Each face: its normal n and two in-plane axes u, v with u × v = n.
  const Vector3f faces[6][3] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
  };
  auto scaled = [&](Vector3f v) { return Vector3f(v.x * h.x, v.y * h.y, v.z * h.z); };
  for (const auto& f : faces) {
    auto base = uint32_t(m.positions.size());
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corners) {
      m.positions.push_back(Point3f(0, 0, 0) + scaled(f[0] + f[1] * c[0] + f[2] * c[1]));
      m.normals.emplace_back(f[0]);
      m.uvs.emplace_back((c[0] + 1) / 2, (1 - c[1]) / 2);
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

}  // namespace obscura

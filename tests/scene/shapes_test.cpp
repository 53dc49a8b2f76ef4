// Generated shapes against geometry: a sphere's area and volume converge to 4πr² and 4/3·πr³,
// every face winds outward (the divergence theorem gives the volume only if it does), and the
// shading normals agree with the geometric ones.
#include "obscura/scene/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace obscura {
namespace {

// Signed volume by the divergence theorem: Σ p0 · (p1 × p2) / 6, positive for outward winding.
double signed_volume(const Mesh& m) {
  double v = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    Vector3d a(to_vector(m.positions[m.indices[t]])), b(to_vector(m.positions[m.indices[t + 1]])),
        c(to_vector(m.positions[m.indices[t + 2]]));
    v += dot(a, cross(b, c)) / 6;
  }
  return v;
}

double area(const Mesh& m) {
  double s = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    Vector3d a(to_vector(m.positions[m.indices[t]])), b(to_vector(m.positions[m.indices[t + 1]])),
        c(to_vector(m.positions[m.indices[t + 2]]));
    s += length(cross(b - a, c - a)) / 2;
  }
  return s;
}

TEST(Shapes, SphereConvergesToItsAreaAndVolume) {
  const double pi = std::numbers::pi;
  Mesh coarse = make_sphere(2, 32), fine = make_sphere(2, 256);
  EXPECT_NEAR(area(fine), 4 * pi * 4, 4 * pi * 4 * 1e-3);
  EXPECT_NEAR(signed_volume(fine), 4.0 / 3 * pi * 8, 4.0 / 3 * pi * 8 * 1e-3);
  // An inscribed polyhedron is smaller, and the error shrinks with more segments.
  EXPECT_LT(signed_volume(coarse), signed_volume(fine));
  EXPECT_LT(signed_volume(fine), 4.0 / 3 * pi * 8);
}

TEST(Shapes, BoxHasItsVolumeAndOutwardFaces) {
  Mesh box = make_box({1, 2, 3});
  EXPECT_EQ(box.triangle_count(), 12u);
  EXPECT_NEAR(signed_volume(box), 6, 1e-5);
  EXPECT_NEAR(area(box), 2 * (2 + 3 + 6), 1e-5);
}

TEST(Shapes, ShadingNormalsAgreeWithTheWinding) {
  for (const Mesh& m : {make_sphere(1, 12), make_box({1, 1, 1}), make_rectangle(2, 3)}) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      Point3f p0 = m.positions[m.indices[t]], p1 = m.positions[m.indices[t + 1]],
              p2 = m.positions[m.indices[t + 2]];
      Vector3f g = cross(p1 - p0, p2 - p0);
      EXPECT_GT(dot(m.normals[m.indices[t]], g), 0) << m.name << " triangle " << t / 3;
    }
  }
  Mesh r = make_rectangle(2, 3);
  EXPECT_NEAR(area(r), 6, 1e-6);
  EXPECT_EQ(r.bounds().diagonal().y, 0);
}

}  // namespace
}  // namespace obscura

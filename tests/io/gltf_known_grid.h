// A small known mesh for the compressed-glTF tests: a 5 × 5 grid of vertices over [0, 4]² with
// z = sin(x)·cos(y)/2, its analytic unit normals and uv = (x, y) / 4, two triangles per cell. The
// tests encode it, load the file and compare what comes back with these originals.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "obscura/scene/mesh.h"

namespace obscura::test {

struct KnownGrid {
  static constexpr int kSide = 5;
  std::vector<float> positions, normals, uvs;  // 3, 3 and 2 floats per vertex
  std::vector<uint32_t> indices;

  KnownGrid() {
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i) {
        float x = float(i), y = float(j);
        float z = std::sin(x) * std::cos(y) / 2;
        positions.insert(positions.end(), {x, y, z});
        // Normal of z = f(x, y): (−∂f/∂x, −∂f/∂y, 1), normalized.
        float dx = std::cos(x) * std::cos(y) / 2, dy = -std::sin(x) * std::sin(y) / 2;
        float length = std::sqrt(dx * dx + dy * dy + 1);
        normals.insert(normals.end(), {-dx / length, -dy / length, 1 / length});
        uvs.insert(uvs.end(), {x / 4, y / 4});
      }
    for (uint32_t j = 0; j + 1 < kSide; ++j)
      for (uint32_t i = 0; i + 1 < kSide; ++i) {
        uint32_t a = j * kSide + i, b = a + 1, c = a + kSide, d = c + 1;
        indices.insert(indices.end(), {a, b, d, a, d, c});
      }
  }
  size_t vertex_count() const { return positions.size() / 3; }

  // The original vertex at `p` (grid positions are distinct), or −1.
  int vertex_at(Point3f p, float tolerance) const {
    for (size_t v = 0; v < vertex_count(); ++v)
      if (std::abs(positions[3 * v] - p.x) <= tolerance &&
          std::abs(positions[3 * v + 1] - p.y) <= tolerance &&
          std::abs(positions[3 * v + 2] - p.z) <= tolerance)
        return int(v);
    return -1;
  }

  // Checks that `mesh` is this grid up to vertex order, triangle order and the rotation of each
  // triangle's corners (what Draco's and meshoptimizer's codecs may change), with positions,
  // normals and uvs within the given quantization errors.
  void expect_same(const Mesh& mesh, float position_error, float normal_error,
                   float uv_error) const {
    ASSERT_EQ(mesh.positions.size(), vertex_count());
    ASSERT_EQ(mesh.normals.size(), vertex_count());
    ASSERT_EQ(mesh.uvs.size(), vertex_count());
    ASSERT_EQ(mesh.indices.size(), indices.size());
    std::vector<int> original(vertex_count());
    for (size_t v = 0; v < vertex_count(); ++v) {
      original[v] = vertex_at(mesh.positions[v], position_error);
      ASSERT_GE(original[v], 0) << "decoded vertex " << v << " is no grid vertex";
      size_t o = size_t(original[v]);
      EXPECT_NEAR(mesh.normals[v].x, normals[3 * o], normal_error) << v;
      EXPECT_NEAR(mesh.normals[v].y, normals[3 * o + 1], normal_error) << v;
      EXPECT_NEAR(mesh.normals[v].z, normals[3 * o + 2], normal_error) << v;
      EXPECT_NEAR(mesh.uvs[v].x, uvs[2 * o], uv_error) << v;
      EXPECT_NEAR(mesh.uvs[v].y, uvs[2 * o + 1], uv_error) << v;
    }
    // Every original triangle appears exactly once, corners in the same cyclic order.
    std::vector<int> found(indices.size() / 3, 0);
    for (size_t t = 0; t < mesh.indices.size() / 3; ++t) {
      std::array<int, 3> corners;
      for (int k = 0; k < 3; ++k) corners[size_t(k)] = original[mesh.indices[3 * t + size_t(k)]];
      bool matched = false;
      for (size_t u = 0; u < found.size() && !matched; ++u)
        for (int r = 0; r < 3 && !matched; ++r)
          if (int(indices[3 * u]) == corners[size_t(r)] &&
              int(indices[3 * u + 1]) == corners[size_t((r + 1) % 3)] &&
              int(indices[3 * u + 2]) == corners[size_t((r + 2) % 3)]) {
            ++found[u];
            matched = true;
          }
      EXPECT_TRUE(matched) << "decoded triangle " << t << " is no grid triangle";
    }
    for (size_t u = 0; u < found.size(); ++u) EXPECT_EQ(found[u], 1) << "grid triangle " << u;
  }
};

}  // namespace obscura::test

// Perspective-correct interpolation: a textured plane seen at a grazing angle gives the texture
// coordinate of the point each pixel's ray hits (computed here by ray casting with glm as the
// camera), and differs clearly from affine (screen-space) interpolation.
#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "obscura/raster/pipeline.h"

namespace obscura::raster {
namespace {

constexpr int kW = 320, kH = 240;

struct UvProgram {
  struct Vertex {
    glm::dvec3 position;
    float u, v;
  };
  struct Varyings {
    float u, v;
  };
  glm::dmat4 clip_from_world;
  VertexOutput<Varyings> vertex(const Vertex& in) const {
    glm::dvec4 c = clip_from_world * glm::dvec4(in.position, 1);
    return {{float(c.x), float(c.y), float(c.z), float(c.w)}, {in.u, in.v}};
  }
  Rgb fragment(const Varyings& v, FragmentInfo) const { return {v.u, v.v, 0}; }
};

TEST(Interpolation, GrazingTexturedPlaneIsPerspectiveCorrect) {
  const glm::dvec3 eye(0, 0.3, 0);
  glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0, 0, -10), glm::dvec3(0, 1, 0));
  glm::dmat4 proj = glm::perspective(glm::radians(50.0), double(kW) / kH, 0.1, 100.0);
  UvProgram program{proj * view};
  // Vertices snap to 1/256 pixel, which moves v by up to (1/512 px)·∂v/∂y ≈ 3e-4 at the far
  // edge at this resolution; the tolerance below leaves room for that and no more.
  // The plane y = 0, x in [−2, 2], z in [−1, −12] (1.4° from grazing at the far edge); u along x, v
  // along −z.
  const double x0 = -2, x1 = 2, z0 = -1, z1 = -12;
  std::vector<UvProgram::Vertex> quad = {
      {{x0, 0, z0}, 0, 0}, {{x1, 0, z0}, 1, 0}, {{x1, 0, z1}, 1, 1}, {{x0, 0, z1}, 0, 1}};
  std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
  RenderTarget target(kW, kH);
  target.clear(Rgb(-1.f));
  draw(target, DrawState{}, program, quad, indices);

  // Projected vertices for the affine comparison.
  auto project = [&](glm::dvec3 p) {
    glm::dvec4 c = proj * view * glm::dvec4(p, 1);
    return glm::dvec2((c.x / c.w + 1) * 0.5 * kW, (1 - c.y / c.w) * 0.5 * kH);
  };
  glm::dmat4 world_from_clip = glm::inverse(proj * view);
  double max_error = 0, max_affine_difference = 0;
  int checked = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double px = x + 0.5, py = y + 0.5;
      glm::dvec4 far = world_from_clip * glm::dvec4(2 * px / kW - 1, 1 - 2 * py / kH, 1, 1);
      glm::dvec3 dir = glm::dvec3(far) / far.w - eye;
      if (dir.y >= 0) continue;
      glm::dvec3 hit = eye + dir * (-eye.y / dir.y);
      double u = (hit.x - x0) / (x1 - x0), v = (hit.z - z0) / (z1 - z0);
      // Away from the quad's outline by more than the snapping can move it.
      if (u < 0.01 || u > 0.99 || v < 0.01 || v > 0.99) continue;
      Rgb got = target.color_at(x, y);
      max_error = std::max({max_error, std::abs(got.r - u), std::abs(got.g - v)});
      // Affine: screen-space barycentrics in whichever half holds the pixel.
      for (int t = 0; t < 2; ++t) {
        const UvProgram::Vertex& a = quad[indices[3 * t]];
        const UvProgram::Vertex& b = quad[indices[3 * t + 1]];
        const UvProgram::Vertex& c = quad[indices[3 * t + 2]];
        glm::dvec2 pa = project(a.position), pb = project(b.position), pc = project(c.position);
        auto cross = [](glm::dvec2 p, glm::dvec2 q) { return p.x * q.y - p.y * q.x; };
        double area = cross(pb - pa, pc - pa);
        double lb = cross(glm::dvec2(px, py) - pa, pc - pa) / area;
        double lc = cross(pb - pa, glm::dvec2(px, py) - pa) / area;
        if (lb < 0 || lc < 0 || lb + lc > 1) continue;
        double affine_v = a.v + lb * (b.v - a.v) + lc * (c.v - a.v);
        max_affine_difference = std::max(max_affine_difference, std::abs(affine_v - v));
      }
      ++checked;
    }
  EXPECT_GT(checked, 3000);
  EXPECT_LT(max_error, 1e-3);
  EXPECT_GT(max_affine_difference, 0.1);  // the test would catch affine interpolation
}

}  // namespace
}  // namespace obscura::raster

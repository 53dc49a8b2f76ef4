// Clipping: triangles crossing the near plane are cut (not dropped, not inverted), triangles
// behind the camera vanish; checked against ray casting through each pixel centre with glm's
// perspective matrix as the independent camera.
#include "obscura/raster/clipper.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "raster/raster_test_util.h"

namespace obscura::raster {
namespace {

constexpr int kW = 80, kH = 60;
constexpr double kNear = 0.5, kFar = 40;

glm::dmat4 projection() {
  return glm::perspective(glm::radians(60.0), double(kW) / kH, kNear, kFar);
}

std::vector<Vector4f> to_clip(const std::vector<glm::dvec3>& eye_points) {
  std::vector<Vector4f> clip;
  for (const glm::dvec3& p : eye_points) {
    glm::dvec4 c = projection() * glm::dvec4(p, 1);
    clip.push_back({float(c.x), float(c.y), float(c.z), float(c.w)});
  }
  return clip;
}

// The ray from the eye through image point (x, y) hits triangle (a, b, c) between the near and
// far planes (Möller–Trumbore in eye space).
bool ray_hits(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double x, double y) {
  glm::dmat4 inv = glm::inverse(projection());
  glm::dvec4 ndc(2 * x / kW - 1, 1 - 2 * y / kH, -1, 1);
  glm::dvec4 p = inv * ndc;
  glm::dvec3 dir = glm::normalize(glm::dvec3(p) / p.w);
  glm::dvec3 e1 = b - a, e2 = c - a, s = glm::cross(dir, e2);
  double det = glm::dot(e1, s);
  if (std::abs(det) < 1e-15) return false;
  glm::dvec3 t0 = -a;  // ray origin is the eye (0, 0, 0)
  double u = glm::dot(t0, s) / det;
  glm::dvec3 q = glm::cross(t0, e1);
  double v = glm::dot(dir, q) / det, t = glm::dot(e2, q) / det;
  if (u < 0 || v < 0 || u + v > 1 || t <= 0) return false;
  double depth = -(t * dir.z);
  return depth >= kNear && depth <= kFar;
}

TEST(Clipper, PolygonCrossingNearPlaneBecomesAQuadInsideIt) {
  using V = test::ClipSpaceProgram::Varyings;
  std::vector<Vector4f> clip = to_clip({{-1, -1, -3}, {1, -1, -3}, {0, 1, 2}});
  VertexOutput<V> poly[kMaxClippedVertices];
  uint32_t planes = 0;
  GuardBand guard = GuardBand::for_viewport(kW, kH);
  for (int i = 0; i < 3; ++i) poly[i] = {clip[i], {float(i)}}, planes |= outcode(clip[i], guard);
  EXPECT_TRUE(planes & kClipNear);
  int n = clip_polygon(poly, 3, planes, guard);
  ASSERT_EQ(n, 4);
  for (int i = 0; i < n; ++i) EXPECT_GE(poly[i].clip.z + poly[i].clip.w, -1e-5f);
}

TEST(Clipper, TriangleCrossingNearPlaneIsCutNotDroppedOrInverted) {
  // One vertex behind the camera, two in front, in both windings.
  std::vector<glm::dvec3> tri = {{-2, -1.5, -4}, {2.5, -0.5, -6}, {0.3, 1.2, 1.5}};
  for (int winding = 0; winding < 2; ++winding) {
    if (winding) std::swap(tri[1], tri[2]);
    std::vector<uint32_t> ids = test::visible_ids(kW, kH, to_clip(tri));
    int agree = 0, ambiguous = 0, covered = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        bool hit = ray_hits(tri[0], tri[1], tri[2], x + 0.5, y + 0.5);
        // Centres within 1/50 pixel of the outline may go either way after snapping.
        bool robust = true;
        for (auto [dx, dy] : {std::pair{0.02, 0.0}, {-0.02, 0.0}, {0.0, 0.02}, {0.0, -0.02}})
          robust &= ray_hits(tri[0], tri[1], tri[2], x + 0.5 + dx, y + 0.5 + dy) == hit;
        if (!robust) {
          ++ambiguous;
          continue;
        }
        EXPECT_EQ(ids[y * kW + x] != 0, hit) << x << "," << y;
        agree += (ids[y * kW + x] != 0) == hit;
        covered += hit;
      }
    EXPECT_EQ(agree, kW * kH - ambiguous);
    EXPECT_GT(covered, 1000);
    EXPECT_LT(ambiguous, 20);
  }
}

TEST(Clipper, TrianglesBehindTheCameraOrBeyondFarDrawNothing) {
  std::vector<Vector4f> clip = to_clip({{-1, -1, 3},
                                        {1, -1, 3},
                                        {0, 1, 3},  // behind
                                        {-1, -1, -50},
                                        {1, -1, -50},
                                        {0, 1, -50},  // beyond far
                                        {-1, -1, 0.2},
                                        {1, -1, 0.1},
                                        {0, 1, 0.3}});  // behind
  std::vector<uint32_t> ids = test::visible_ids(kW, kH, clip);
  for (uint32_t id : ids) ASSERT_EQ(id, 0u);
}

TEST(Clipper, ClippedDepthMatchesTheProjection) {
  // A wall at eye depth 5 crossing the near plane: window depth = (ndc_z + 1)/2 everywhere.
  std::vector<glm::dvec3> tri = {{-20, -20, -5}, {20, -20, -5}, {0, 20, 1}};
  std::vector<Vector4f> clip = to_clip(tri);
  RenderTarget target(kW, kH, 1, true);
  target.clear();
  draw(target, DrawState{}, test::ClipSpaceProgram{}, clip);
  int checked = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (!ray_hits(tri[0], tri[1], tri[2], x + 0.5, y + 0.5)) continue;
      // Eye depth along the ray through this pixel, then glm's projection of that point.
      glm::dmat4 inv = glm::inverse(projection());
      glm::dvec4 p = inv * glm::dvec4(2 * (x + 0.5) / kW - 1, 1 - 2 * (y + 0.5) / kH, -1, 1);
      glm::dvec3 dir = glm::dvec3(p) / p.w;
      // The plane through the three points.
      glm::dvec3 n = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
      double t = glm::dot(n, tri[0]) / glm::dot(n, dir);
      glm::dvec4 c = projection() * glm::dvec4(dir * t, 1);
      double expected = c.z / c.w * 0.5 + 0.5;
      EXPECT_NEAR(target.depth_at(x, y), expected, 1e-5) << x << "," << y;
      EXPECT_NEAR(target.view_depth_at(x, y), -(dir * t).z, 1e-4 * -(dir * t).z);
      ++checked;
    }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace obscura::raster

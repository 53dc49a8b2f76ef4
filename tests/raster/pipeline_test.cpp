// The pipeline as a whole: depth testing and submission order, culling, MSAA coverage,
// determinism across thread counts, input validation.
#include "obscura/raster/pipeline.h"

#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include "obscura/math/error.h"
#include "obscura/raster/shaders.h"
#include "raster/raster_test_util.h"

namespace obscura::raster {
namespace {

using test::pixel_to_clip;
using test::visible_ids;

constexpr int kW = 48, kH = 40;

std::vector<Vector4f> interpenetrating(bool reversed) {
  // Two triangles crossing each other in depth; their intersection line splits the overlap.
  std::vector<Vector4f> a = {pixel_to_clip(2.3, 3.1, kW, kH, -0.6),
                             pixel_to_clip(45.7, 8.4, kW, kH, 0.7),
                             pixel_to_clip(20.2, 38.9, kW, kH, 0.1)};
  std::vector<Vector4f> b = {pixel_to_clip(5.1, 35.3, kW, kH, 0.65),
                             pixel_to_clip(44.2, 37.6, kW, kH, -0.55),
                             pixel_to_clip(25.6, 1.7, kW, kH, 0.2)};
  std::vector<Vector4f> clip = reversed ? b : a;
  for (const Vector4f& v : reversed ? a : b) clip.push_back(v);
  return clip;
}

TEST(Pipeline, OverlappingTrianglesGiveTheSameImageInBothOrders) {
  std::vector<uint32_t> forward = visible_ids(kW, kH, interpenetrating(false));
  std::vector<uint32_t> backward = visible_ids(kW, kH, interpenetrating(true));
  int both = 0;
  std::vector<int> seen(3, 0);
  for (size_t i = 0; i < forward.size(); ++i) {
    // Primitive 0 of one order is primitive 1 of the other.
    uint32_t mapped = backward[i] == 0 ? 0 : 3 - backward[i];
    ASSERT_EQ(forward[i], mapped) << "pixel " << i;
    ++seen[forward[i]];
  }
  both = seen[1] > 100 && seen[2] > 100;
  EXPECT_TRUE(both) << "both triangles should win somewhere";
}

TEST(Pipeline, OnEqualDepthTheFirstDrawnWinsForLess) {
  std::vector<Vector4f> tri = {pixel_to_clip(3.3, 4.1, kW, kH, 0.3),
                               pixel_to_clip(40.6, 9.7, kW, kH, -0.2),
                               pixel_to_clip(12.2, 35.9, kW, kH, 0.5)};
  // The same triangle again, its vertices rotated and reflected.
  std::vector<Vector4f> clip = tri;
  for (int k : {1, 2, 0}) clip.push_back(tri[k]);
  for (int k : {2, 1, 0}) clip.push_back(tri[k]);
  std::vector<uint32_t> less = visible_ids(kW, kH, clip, DepthFunc::kLess);
  std::vector<uint32_t> lequal = visible_ids(kW, kH, clip, DepthFunc::kLessEqual);
  int covered = 0;
  for (size_t i = 0; i < less.size(); ++i) {
    if (less[i] == 0) continue;
    ++covered;
    EXPECT_EQ(less[i], 1u);
    EXPECT_EQ(lequal[i], 3u);
  }
  EXPECT_GT(covered, 300);
}

TEST(Pipeline, BackFaceCullingUsesWindingInNdc) {
  // Counter-clockwise in NDC (y up): front-facing by OpenGL's default.
  std::vector<Vector4f> ccw = {{-0.8f, -0.8f, 0, 1}, {0.8f, -0.8f, 0, 1}, {0, 0.8f, 0, 1}};
  auto count = [&](CullMode cull, const std::vector<Vector4f>& clip) {
    int n = 0;
    for (int c : test::coverage_counts(kW, kH, clip, cull)) n += c;
    return n;
  };
  std::vector<Vector4f> cw = {ccw[0], ccw[2], ccw[1]};
  EXPECT_GT(count(CullMode::kBack, ccw), 0);
  EXPECT_EQ(count(CullMode::kFront, ccw), 0);
  EXPECT_EQ(count(CullMode::kBack, cw), 0);
  EXPECT_EQ(count(CullMode::kNone, cw), count(CullMode::kBack, ccw));
}

TEST(Pipeline, MsaaCoverageFollowsTheStandardSamplePatterns) {
  // A vertical edge through the centres of column 10: of the D3D patterns' samples (x offsets
  // −2, 6, −6, 2 sixteenths for 4×; 1, −1, 5, −3, −5, −7, 3, 7 for 8×), those with positive
  // offset lie right of it.
  for (auto [samples, expected] : {std::pair{4, 0.5f}, {8, 0.5f}}) {
    RenderTarget target(kW, kH, samples);
    target.clear();
    std::vector<Vector4f> clip = {pixel_to_clip(10.5, 2.25, kW, kH),
                                  pixel_to_clip(30, 2.25, kW, kH),
                                  pixel_to_clip(10.5, 30.75, kW, kH)};
    draw(target, DrawState{}, test::ClipSpaceProgram{}, clip);
    Image resolved = target.resolve_color();
    EXPECT_FLOAT_EQ(resolved.at(10, 10, 0), expected) << samples;
    EXPECT_FLOAT_EQ(resolved.at(12, 10, 0), 1.f) << samples;
    EXPECT_FLOAT_EQ(resolved.at(9, 10, 0), 0.f) << samples;
  }
  // A horizontal edge through row 20's centres, triangle above: y offsets 6 and 2 (4×) lie
  // below the centre, so 2 of 4 samples fall outside.
  RenderTarget target(kW, kH, 4);
  target.clear();
  std::vector<Vector4f> clip = {pixel_to_clip(5.25, 3.25, kW, kH),
                                pixel_to_clip(40.75, 20.5, kW, kH),
                                pixel_to_clip(5.25, 20.5, kW, kH)};
  draw(target, DrawState{}, test::ClipSpaceProgram{}, clip);
  EXPECT_FLOAT_EQ(target.resolve_color().at(8, 20, 0), 0.5f);
}

std::vector<MeshVertex> sphere_grid(int rings, int segments, std::vector<uint32_t>* indices) {
  std::vector<MeshVertex> v;
  for (int gy = 0; gy < 3; ++gy)
    for (int gx = 0; gx < 4; ++gx) {
      uint32_t base = uint32_t(v.size());
      for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
          float phi = float(M_PI) * r / rings, theta = 2 * float(M_PI) * s / segments;
          Vector3f n(std::sin(phi) * std::cos(theta), std::cos(phi),
                     std::sin(phi) * std::sin(theta));
          v.push_back({Point3f(gx * 2.2f - 3.3f + n.x, gy * 2.2f - 2.2f + n.y, n.z),
                       n,
                       {},
                       Rgb(0.7f, 0.5f, 0.3f),
                       1.f,
                       {},
                       {}});
        }
      for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
          uint32_t a = base + r * (segments + 1) + s, b = a + 1, c = a + segments + 1, d = c + 1;
          for (uint32_t i : {a, c, b, b, c, d}) indices->push_back(i);
        }
    }
  return v;
}

// The grid of spheres under one light, Blinn-Phong per pixel, drawn into `target`.
void draw_sphere_grid(RenderTarget& target) {
  std::vector<uint32_t> indices;
  std::vector<MeshVertex> vertices = sphere_grid(40, 60, &indices);
  LightSet lights;
  lights.directional.push_back({normalize(Vector3f(0.4f, 0.6f, 0.7f)), Rgb(1.f)});
  PhongProgram<SpecularModel::kBlinnPhong> program;
  Matrix4 clip_from_world =
      Matrix4::from_rows({{{1.2, 0, 0, 0}, {0, 1.6, 0, 0}, {0, 0, -1.02, -2.02}, {0, 0, -1, 0}}}) *
      Matrix4::from_rows({{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, -8}, {0, 0, 0, 1}}});
  program.scene = {Matrix4f(clip_from_world), Point3f(0, 0, 8), &lights};
  program.material.specular = Rgb(0.5f);
  draw(target, DrawState{}, program, vertices, indices);
}

TEST(Pipeline, IdenticalOutputForAnyThreadCount) {
  auto render = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    RenderTarget target(300, 200, 1, true);
    target.clear();
    draw_sphere_grid(target);
    return target.resolve_color().data;
  };
  std::vector<float> one = render(1), many = render(4);
  ASSERT_EQ(one.size(), many.size());
  int lit = 0;
  for (size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i], many[i]) << "value " << i;
    lit += one[i] != 0;
  }
  EXPECT_GT(lit, 30000);
}

// The tile loop is compiled twice (baseline and AVX2 + FMA, chosen at run time); the copy the
// machine does not pick would otherwise go untested. Coverage and depth order are exact in both,
// so the ids agree everywhere; colours differ only by roundings (fused multiply-adds).
TEST(Pipeline, BaselineAndAvx2CopiesAgree) {
  const bool machine_default = use_avx2().load();
  auto render = [&](bool avx2) {
    use_avx2() = avx2 && machine_default;
    RenderTarget target(301, 203, 1, true);  // odd sizes: partial blocks at the right and bottom
    target.clear(Rgb(0.1f, 0.2f, 0.3f));
    draw_sphere_grid(target);
    use_avx2() = machine_default;
    return target;
  };
  RenderTarget baseline = render(false), avx2 = render(true);
  int lit = 0;
  for (int y = 0; y < baseline.height(); ++y)
    for (int x = 0; x < baseline.width(); ++x) {
      ASSERT_EQ(baseline.object_id_at(x, y), avx2.object_id_at(x, y)) << x << "," << y;
      ASSERT_EQ(baseline.primitive_id_at(x, y), avx2.primitive_id_at(x, y)) << x << "," << y;
      Rgb a = baseline.color_at(x, y), b = avx2.color_at(x, y);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], 1e-5f * (1 + std::abs(a[c])));
      lit += baseline.object_id_at(x, y) != kNoObject;
    }
  EXPECT_GT(lit, 10000);
  if (!machine_default) GTEST_LOG_(INFO) << "no AVX2 + FMA here: both renders used the baseline";
}

TEST(Pipeline, RejectsBadIndicesAndCounts) {
  RenderTarget target(8, 8);
  std::vector<Vector4f> clip(3, Vector4f(0, 0, 0, 1));
  EXPECT_THROW(draw(target, DrawState{}, test::ClipSpaceProgram{}, clip, {0, 1, 3}), Error);
  EXPECT_THROW(draw(target, DrawState{}, test::ClipSpaceProgram{}, clip, {0, 1}), Error);
  EXPECT_THROW(RenderTarget(8, 8, 2), Error);
}

}  // namespace
}  // namespace obscura::raster

// glTF alpha coverage in the tracer (alphaMode MASK and BLEND), against the specification's
// definitions: MASK shows the surface exactly where alpha ≥ alphaCutoff; BLEND lets a fraction
// 1 − alpha of what lies behind show through. Two quads face the camera: a white one in front
// with coverage, a black one behind it.
#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <cmath>
#include <tuple>

#include "obscura/film/film.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

// `front` covers the view at z = 0, a black quad lies behind at z = −1.
Scene two_layers(Material front, const Texture* alpha_texture = nullptr) {
  Scene scene;
  MetallicRoughnessMaterial black;
  black.base_color = Rgb(0.f);
  black.metallic = 0;
  black.specular = 0;
  Material back;
  back.name = "back";
  back.model = black;
  scene.materials = {std::move(front), back};
  Mesh near = testing::make_quad("front", 0, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
  near.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  Mesh far = testing::make_quad("back", 1, {-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1});
  if (alpha_texture) scene.textures.push_back(*alpha_texture);
  scene.add_meshes({near, far});
  scene.camera = testing::make_camera({0, 0, 3}, {0, 0, 0}, 16, 30);
  return scene;
}

Material white_with_alpha(AlphaMode mode, float alpha, float cutoff = 0.5f) {
  MetallicRoughnessMaterial mr;
  mr.base_color = Rgb(1.f);
  mr.alpha = alpha;
  mr.metallic = 0;
  mr.specular = 0;  // purely diffuse: the furnace gives exactly its colour
  Material m;
  m.name = "front";
  m.model = mr;
  m.alpha_mode = mode;
  m.alpha_cutoff = cutoff;
  return m;
}

// The fraction of camera-like rays (distinct origins, all towards −z) that stop at the front quad.
double front_hits(const TraceScene& trace, int n) {
  int front = 0;
  for (int i = 0; i < n; ++i) {
    Ray ray;
    ray.origin = {-1 + 2 * float(i % 100) / 100, -1 + 2 * float(i / 100) / 100, 3};
    ray.direction = {0, 0, -1};
    std::optional<SurfaceHit> hit = trace.intersect(ray);
    if (hit && hit->position.z > -0.5f) ++front;
  }
  return double(front) / n;
}

TEST(AlphaCoverage, MaskCutsOutBelowTheCutoffOnly) {
  for (auto [alpha, cutoff, visible] : {std::tuple{0.3f, 0.5f, false}, std::tuple{0.3f, 0.2f, true},
                                        std::tuple{0.5f, 0.5f, true}}) {
    Scene scene = two_layers(white_with_alpha(AlphaMode::kMask, alpha, cutoff));
    TraceScene trace(scene, testing::embree_device());
    EXPECT_EQ(front_hits(trace, 1000), visible ? 1.0 : 0.0) << alpha << " " << cutoff;
    // Shadow rays (to between the quads) agree with camera rays.
    Ray through{{0, 0, 3}, {0, 0, -1}, 0, 3.5f};
    EXPECT_EQ(trace.occluded(through), visible);
  }
}

TEST(AlphaCoverage, OpaqueIgnoresAlpha) {
  Scene scene = two_layers(white_with_alpha(AlphaMode::kOpaque, 0.f));
  TraceScene trace(scene, testing::embree_device());
  EXPECT_EQ(front_hits(trace, 1000), 1.0);
}

TEST(AlphaCoverage, BlendStopsAFractionAlphaOfTheRays) {
  Scene scene = two_layers(white_with_alpha(AlphaMode::kBlend, 0.25f));
  TraceScene trace(scene, testing::embree_device());
  const int n = 10000;
  // Binomial: σ = √(0.25 · 0.75 / n) ≈ 0.0043.
  EXPECT_NEAR(front_hits(trace, n), 0.25, 5 * 0.0043);
}

TEST(AlphaCoverage, TextureAlphaMasksPerTexel) {
  // Alpha 0 in the left texel, 1 in the right: only the right half of the quad remains.
  Texture alpha;
  alpha.width = 2, alpha.height = 1, alpha.channels = 4;
  alpha.texels_8bit = {255, 255, 255, 0, 255, 255, 255, 255};
  alpha.encoding = TextureEncoding::kSrgb;
  alpha.filter = TextureFilter::kNearest;
  Material front = white_with_alpha(AlphaMode::kMask, 1.f);
  std::get<MetallicRoughnessMaterial>(front.model).base_color_texture.texture = 0;
  Scene scene = two_layers(front, &alpha);
  TraceScene trace(scene, testing::embree_device());
  for (float x : {-1.5f, -0.5f, 0.5f, 1.5f}) {
    std::optional<SurfaceHit> hit = trace.intersect(Ray{{x, 0, 3}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->position.z > -0.5f, x > 0) << x;
  }
}

TEST(AlphaCoverage, VertexColourAlphaMultipliesTheCoverage) {
  // Factor 0.8 × COLOR_0 alpha: 0.8 × 0.7 = 0.56 stays above a cutoff of 0.5, 0.8 × 0.6 = 0.48
  // falls below it.
  for (auto [vertex_alpha, visible] : {std::pair{0.7f, true}, std::pair{0.6f, false}}) {
    Scene scene = two_layers(white_with_alpha(AlphaMode::kMask, 0.8f));
    scene.meshes[0].color_alphas.assign(4, vertex_alpha);
    TraceScene trace(scene, testing::embree_device());
    EXPECT_EQ(front_hits(trace, 1000), visible ? 1.0 : 0.0) << vertex_alpha;
  }
}

TEST(AlphaCoverage, BlendInTheFurnaceMixesFrontAndBack) {
  // Under a uniform environment of radiance 1 the white diffuse front quad shows 1 and the black
  // back quad 0: a blend with alpha 0.4 shows 0.4, whatever the thread count.
  Scene scene = two_layers(white_with_alpha(AlphaMode::kBlend, 0.4f));
  TraceScene trace(scene, testing::embree_device());
  trace.set_environment(EnvironmentLight(Rgb(1.f)));
  Film one(16, 16), many(16, 16);
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    render(trace, scene.camera, PathTracer(), {.samples_per_pixel = 256, .seed = 3}, one);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 3);
    render(trace, scene.camera, PathTracer(), {.samples_per_pixel = 256, .seed = 3}, many);
  }
  Rgb sum;
  for (int y = 4; y < 12; ++y)
    for (int x = 4; x < 12; ++x) {
      sum += one.pixel({x, y});
      for (int c = 0; c < 3; ++c) EXPECT_EQ(one.pixel({x, y})[c], many.pixel({x, y})[c]);
    }
  EXPECT_NEAR(sum.g / 64, 0.4f, 0.02f);
}

}  // namespace
}  // namespace obscura

// glTF's per-vertex COLOR_0 and emission textures in the tracer: each checked against a scene
// that is physically the same but built without the feature.
#include <gtest/gtest.h>

#include "obscura/film/film.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

Rgb region_mean(const Film& film, Bounds2i region) {
  Rgb sum;
  for (int y = region.min.y; y < region.max.y; ++y)
    for (int x = region.min.x; x < region.max.x; ++x) sum += film.pixel({x, y});
  return sum / float(region.width() * region.height());
}

TEST(VertexColors, MultiplyTheBaseColourInTheFurnace) {
  // A white Lambertian quad filling the view, in a uniform environment of radiance 1: it reflects
  // exactly its colour, here the vertex colour (constant over the quad).
  Scene scene;
  scene.materials = {diffuse_material("white", Rgb(1.f))};
  Mesh quad = testing::make_quad("quad", 0, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0});
  const Rgb color(1.f, 0.5f, 0.25f);
  quad.colors.assign(4, color);
  scene.add_meshes({quad});
  Camera camera = testing::make_camera({0, 0, 3}, {0, 0, 0}, 16, 30);
  scene.camera = camera;
  TraceScene trace(scene, testing::embree_device());
  trace.set_environment(EnvironmentLight(Rgb(1.f)));
  Film film(16, 16);
  render(trace, camera, PathTracer(), {.samples_per_pixel = 64, .seed = 1}, film);
  Rgb mean = region_mean(film, {{0, 0}, {16, 16}});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], color[c], 0.01f * color[c] + 2e-3f) << c;
}

// A 1 m square light at height 1 facing down over a grey floor: either the left half of it
// emits through a texture (white texel left, black texel right) or it is a half-size untextured
// light. The two scenes send the same light to the floor.
Scene lamp_scene(bool textured) {
  Scene scene;
  Material lamp = diffuse_material("lamp", Rgb(0.f), Rgb(4.f));
  scene.materials = {diffuse_material("floor", Rgb(0.5f)), lamp};
  Mesh floor = testing::make_quad("floor", 0, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2});
  Mesh light;
  if (textured) {
    light = testing::make_quad("lamp", 1, {-0.5f, 1, -0.5f}, {0.5f, 1, -0.5f}, {0.5f, 1, 0.5f},
                               {-0.5f, 1, 0.5f});
    light.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    Texture half;
    half.width = 2, half.height = 1, half.channels = 3;
    half.texels_8bit = {255, 255, 255, 0, 0, 0};
    half.encoding = TextureEncoding::kLinear;
    half.filter = TextureFilter::kNearest;
    scene.textures.push_back(half);
    scene.materials[1].emission_texture.texture = 0;
  } else {
    light = testing::make_quad("lamp", 1, {-0.5f, 1, -0.5f}, {0, 1, -0.5f}, {0, 1, 0.5f},
                               {-0.5f, 1, 0.5f});
  }
  scene.add_meshes({floor, light});
  // Low and looking down at the floor: the lamp stays out of view.
  scene.camera = testing::make_camera({0, 0.6, 3}, {0, 0, -0.5}, 24, 30);
  return scene;
}

TEST(TexturedEmission, LightsLikeTheSameLightWithoutATexture) {
  using Strategy = PathTracerSettings::Strategy;
  std::vector<Film> films;
  for (auto [textured, strategy] :
       {std::pair{true, Strategy::kMis}, std::pair{true, Strategy::kBsdfOnly},
        std::pair{false, Strategy::kMis}}) {
    Scene scene = lamp_scene(textured);
    TraceScene trace(scene, testing::embree_device());
    films.emplace_back(24, 24);
    render(trace, scene.camera, PathTracer({.max_depth = 4, .strategy = strategy}),
           {.samples_per_pixel = strategy == Strategy::kBsdfOnly ? 1024 : 256, .seed = 2},
           films.back());
  }
  // The left and right halves of the floor (the light's texture is not symmetric).
  for (Bounds2i r : {Bounds2i{{0, 0}, {12, 24}}, Bounds2i{{12, 0}, {24, 24}}}) {
    float reference = luminance(region_mean(films[2], r));
    ASSERT_GT(reference, 0.01f);
    EXPECT_NEAR(luminance(region_mean(films[0], r)) / reference, 1.0, 0.03) << "light sampling";
    EXPECT_NEAR(luminance(region_mean(films[1], r)) / reference, 1.0, 0.05) << "BSDF sampling";
  }
  // Not symmetric: the lit half of the lamp is on the left.
  EXPECT_GT(luminance(region_mean(films[0], {{0, 0}, {12, 24}})),
            1.2f * luminance(region_mean(films[0], {{12, 0}, {24, 24}})));
}

TEST(TexturedEmission, SeenDirectlyTheTextureShows) {
  // Looking up at the lamp from below: one half of it is 4 (the texel's 1 times the factor), the
  // other black.
  Scene scene = lamp_scene(true);
  Camera camera = testing::make_camera({0, 0.2, 0}, {0, 0, -1}, 16, 20);
  camera.world_from_camera = world_from_camera_look_at({0, 0.2, 0}, {0, 1, 0}, {0, 0, -1});
  TraceScene trace(scene, testing::embree_device());
  Film film(16, 16);
  render(trace, camera, PathTracer({.max_depth = 1}), {.samples_per_pixel = 4, .seed = 1}, film);
  float a = film.pixel({2, 8}).g, b = film.pixel({13, 8}).g;
  EXPECT_NEAR(std::max(a, b), 4.f, 1e-4f);
  EXPECT_NEAR(std::min(a, b), 0.f, 1e-4f);
}

}  // namespace
}  // namespace obscura

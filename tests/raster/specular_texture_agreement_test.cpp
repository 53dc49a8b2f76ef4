// KHR_materials_specular's textures in the rasterizer against the tracer: a dielectric floor whose
// specular strength (the specular texture's A) varies from left to right and whose specular
// colour (the specular colour texture's RGB) varies from far to near, under a point light and a
// directional light placed for a highlight. The tracer's direct lighting (one sample at each
// pixel centre, deterministic for punctual lights) is the reference; the rasterizer must agree
// with it away from silhouettes, and must not agree once the textures are taken away (the
// textures matter to the image, so the agreement says they are read alike).
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "direct_light_reference.h"
#include "obscura/camera/frames.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/shapes.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "raster_images.h"

namespace obscura::raster {
namespace {

using test_images::trace_direct;
using test_images::with_film;

test_images::RasterImages rasterize(const Scene& scene, const Camera& camera) {
  RasterSettings settings;
  settings.shadow_map_size = 0;  // nothing to shadow
  return test_images::rasterize_with_aovs(scene, camera, settings);
}

// A 4 × 4 linear float texture, texel (x, y) from `texel`. Few texels over many pixels: both
// renderers then read it bilinearly at full resolution (the rasterizer's mipmap is not used).
template <class F>
obscura::Texture texture_4x4(int channels, F texel) {
  obscura::Texture t;
  t.width = t.height = 4;
  t.channels = channels;
  t.encoding = TextureEncoding::kLinear;
  t.wrap_u = t.wrap_v = TextureWrap::kClampToEdge;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < channels; ++c) t.texels_float.push_back(texel(x, y, c));
  return t;
}

Scene specular_floor() {
  Scene scene;
  // Strength in A from 0.05 (left) to 1 (right); the RGB is not read.
  scene.textures.push_back(texture_4x4(4, [](int x, int, int c) {
    const float strength[4] = {0.05f, 0.35f, 0.7f, 1.f};
    return c == 3 ? strength[x] : 1.f;
  }));
  // Colour by row: red, green, blue, white.
  scene.textures.push_back(texture_4x4(3, [](int, int y, int c) {
    const float rows[4][3] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.2f, 0.2f, 1}, {1, 1, 1}};
    return rows[y][c];
  }));
  MetallicRoughnessMaterial m;
  m.base_color = Rgb(0.1f);  // dark, so that the specular layer shows
  m.metallic = 0;
  m.roughness = 0.35f;
  m.specular_color = Rgb(3.f);  // F0 up to 0.12 where the colour texture is white
  m.specular_texture.texture = 0;
  m.specular_color_texture.texture = 1;
  Material material;
  material.model = m;
  scene.materials.push_back(material);
  scene.add_mesh(make_rectangle(2, 2));
  scene.lights = {
      // Mirrored about the floor's normal from the camera: a broad highlight mid-floor.
      {"sun", obscura::DirectionalLight{.direction = normalize(Vector3f(0, -2.2f, 0.8f)),
                                        .irradiance = Rgb(2.f)}},
      {"bulb", obscura::PointLight{.position = {0.4f, 0.5f, 0.2f}, .intensity = Rgb(0.6f)}}};
  scene.camera.world_from_camera = world_from_camera_look_at({0, 2.2, 0.8}, {0, 0, 0});
  scene.camera.projection = Perspective::from_horizontal_fov_degrees(60);
  return scene;
}

TEST(SpecularTextureAgreement, RasterizerReadsSpecularTexturesAsTheTracer) {
  const Scene scene = specular_floor();
  const Camera camera = with_film(scene.camera, 160, 120);
  const test_images::TracedImages traced = trace_direct(scene, camera);
  const test_images::RasterImages raster = rasterize(scene, camera);
  const test_images::ColourAgreement a =
      test_images::compare_colours(traced.color, traced.id, raster.color, raster.id);
  ASSERT_GT(a.compared, 8000);
  EXPECT_GT(a.lit[0], 1000) << "the floor is hardly lit";
  std::printf("    %d pixels: mean relative difference %.2e, max %.2e\n", a.compared,
              a.mean_relative, a.max_relative);
  EXPECT_LT(a.mean_relative, 1e-3);
  EXPECT_LT(a.max_relative, 0.02);

  // Without its textures the floor is another image: the reference tells the two apart by far
  // more than the tolerance above.
  Scene untextured = scene;
  auto& m = std::get<MetallicRoughnessMaterial>(untextured.materials[0].model);
  m.specular_texture = m.specular_color_texture = {};
  const test_images::RasterImages plain = rasterize(untextured, camera);
  const test_images::ColourAgreement without =
      test_images::compare_colours(traced.color, traced.id, plain.color, plain.id);
  std::printf("    without the textures: mean relative difference %.2e, max %.2e\n",
              without.mean_relative, without.max_relative);
  EXPECT_GT(without.mean_relative, 0.05);
  EXPECT_GT(without.max_relative, 0.3);
}

}  // namespace
}  // namespace obscura::raster

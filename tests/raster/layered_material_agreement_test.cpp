// KHR_materials_clearcoat and KHR_materials_sheen in the rasterizer against the tracer: spheres
// with a coat, a sheen and both, under a directional and a point light, shaded by the tracer's
// direct lighting (one sample at each pixel centre, deterministic for punctual lights) and by
// the rasterizer, which must agree away from silhouettes.
#include <gtest/gtest.h>

#include <cmath>
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
  settings.shadow_map_size = 0;  // no sphere shadows another
  return test_images::rasterize_with_aovs(scene, camera, settings);
}
using test_images::on_silhouette;

Scene layered_spheres() {
  Scene scene;
  MetallicRoughnessMaterial coated;  // a red dielectric under a glossy coat
  coated.base_color = Rgb(0.6f, 0.05f, 0.03f);
  coated.metallic = 0;
  coated.roughness = 0.5f;
  coated.clearcoat = 1;
  coated.clearcoat_roughness = 0.15f;
  MetallicRoughnessMaterial cloth;  // blue cloth with a pale sheen
  cloth.base_color = Rgb(0.05f, 0.1f, 0.5f);
  cloth.metallic = 0;
  cloth.roughness = 0.8f;
  cloth.sheen_color = Rgb(0.9f, 0.8f, 0.7f);
  cloth.sheen_roughness = 0.5f;
  MetallicRoughnessMaterial both = cloth;  // coated metal with a sheen under the coat
  both.base_color = Rgb(0.9f, 0.7f, 0.3f);
  both.metallic = 1;
  both.roughness = 0.4f;
  both.clearcoat = 0.7f;
  both.clearcoat_roughness = 0.3f;
  for (const MetallicRoughnessMaterial& m : {coated, cloth, both}) {
    Material material;
    material.model = m;
    scene.materials.push_back(material);
  }
  for (int i = 0; i < 3; ++i) {
    Mesh sphere = make_sphere(0.5f, 128);
    sphere.material = uint32_t(i);
    scene.add_mesh(std::move(sphere), Transform::translate({-1.2 + 1.2 * i, 0, 0}));
  }
  scene.lights = {
      {"sun", obscura::DirectionalLight{.direction = normalize(Vector3f(-0.4f, -0.8f, -0.6f)),
                                        .irradiance = Rgb(2.f)}},
      {"bulb", obscura::PointLight{.position = {1, 2, 3}, .intensity = Rgb(8.f)}}};
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0.6, 4}, {0, 0, 0});
  scene.camera.projection = Perspective::from_horizontal_fov_degrees(50);
  return scene;
}

TEST(LayeredMaterialAgreement, RasterizerShadesCoatAndSheenAsTheTracer) {
  Scene scene = layered_spheres();
  Camera camera = with_film(scene.camera, 240, 120);
  test_images::TracedImages traced = trace_direct(scene, camera);
  test_images::RasterImages raster = rasterize(scene, camera);
  test_images::ColourAgreement a =
      test_images::compare_colours(traced.color, traced.id, raster.color, raster.id);
  ASSERT_GT(a.compared, 3000);
  for (int i = 0; i < 3; ++i) EXPECT_GT(a.lit[i], 300) << "sphere " << i << " is hardly lit";
  // The same formulas in both renderers: differences are float roundings and the tracer's
  // frame (its coat normal passes through the local frame), far below a per cent.
  std::printf("    %d pixels: mean relative difference %.2e, max %.2e\n", a.compared,
              a.mean_relative, a.max_relative);
  EXPECT_LT(a.mean_relative, 1e-3);
  EXPECT_LT(a.max_relative, 0.02);
}

}  // namespace
}  // namespace obscura::raster

// Regressions from Khronos' TransmissionTest drawn by the rasterizer:
// - its labels are two back-to-back quads 1.6 mm apart, and its camera's near plane is 0.06 mm:
//   with window depth in float, the back quad (black: emission shows on front faces only) won
//   the depth test over whole triangles ("black blocks in the text");
// - KHR_materials_transmission was drawn opaque, so a sphere cut by a MASK showed solid chunks
//   with holes where the path tracer shows glass.
#include <gtest/gtest.h>

#include <vector>

#include "obscura/camera/frames.h"
#include "obscura/raster/scene_rasterizer.h"
#include "raster_images.h"

namespace obscura::raster {
namespace {

constexpr int kSize = 48;

// A quad over [−h, h]² at depth z facing +Z (`flip`: facing −Z), with glTF UVs.
Mesh quad(uint32_t material, float h, float z, bool flip = false) {
  Mesh m;
  m.name = "quad";
  m.positions = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
  m.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  m.indices =
      flip ? std::vector<uint32_t>{0, 2, 1, 0, 3, 2} : std::vector<uint32_t>{0, 1, 2, 0, 2, 3};
  m.material = material;
  return m;
}

// Black, purely diffuse, emitting `emission` from its front face (as TransmissionTest's labels).
Material label(Rgb emission) {
  MetallicRoughnessMaterial mr;
  mr.base_color = Rgb(0.f);
  mr.metallic = 0, mr.specular = 0;
  Material m;
  m.name = "label";
  m.model = mr;
  m.emission = emission;
  return m;
}

Image render(const Scene& scene, Image* ids = nullptr) {
  RasterSettings settings;
  settings.surface_lights = false;
  test_images::RasterImages images =
      test_images::rasterize_with_aovs(scene, scene.camera, settings);
  if (ids) *ids = images.id;
  return images.color;
}

TEST(RasterDepthPrecision, BackToBackQuadsMillimetresApartDoNotFightUnderATinyNearPlane) {
  // TransmissionTest's numbers: near 5.6e-5 m, far 3.08 m, the label 1.5 m away, its back face
  // 1.56 mm behind the front. Both draw orders: the front quad must win every pixel.
  for (bool back_first : {false, true}) {
    Scene scene;
    scene.materials = {label(Rgb(1.f)), label(Rgb(1.f, 0.f, 0.f))};
    std::vector<Mesh> meshes = {quad(0, 0.2f, 0.f), quad(1, 0.2f, -0.00156f, true)};
    if (back_first) std::swap(meshes[0], meshes[1]);
    scene.add_meshes(std::move(meshes));
    scene.camera.world_from_camera = world_from_camera_look_at({0.03, 0.02, 1.5}, {0, 0, 0});
    scene.camera.near_m = 5.606882768915966e-05, scene.camera.far_m = 3.0837855339050293;
    scene.camera.film.width_px = scene.camera.film.height_px = kSize;
    scene.camera.film.filter = BoxFilter{1e-6};
    Image ids;
    Image color = render(scene, &ids);
    const float front_id = back_first ? 1.f : 0.f;
    const float exposure = float(scene.camera.exposure_scale());
    int covered = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (ids.at(x, y, 0) < 0) continue;
        ++covered;
        ASSERT_EQ(ids.at(x, y, 0), front_id) << x << ", " << y << " back first " << back_first;
        ASSERT_NEAR(color.at(x, y, 1), exposure, 1e-5f) << x << ", " << y;
      }
    EXPECT_GT(covered, kSize * kSize / 8);
  }
}

TEST(RasterDepthPrecision, NearPlaneIsNotMovedPastGeometry) {
  // The camera inside the scene's bounds (a quad behind it): the quad 0.2 m in front of it and
  // the wall 4 m away around it must both still be drawn.
  Scene scene;
  scene.materials = {label(Rgb(1.f))};
  scene.add_meshes({quad(0, 0.02f, 0.8f), quad(0, 4.f, -3.f), quad(0, 0.1f, 2.f)});
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0, 1}, {0, 0, 0});
  scene.camera.near_m = 0.01, scene.camera.far_m = 100;
  scene.camera.film.width_px = scene.camera.film.height_px = kSize;
  Image ids;
  render(scene, &ids);
  EXPECT_EQ(ids.at(kSize / 2, kSize / 2, 0), 0.f);
  EXPECT_EQ(ids.at(0, 0, 0), 1.f);
}

// A glTF transmissive surface (base colour tint, transmissionFactor 1, metallic 0) before an
// emitter, no light else: it shows the emitter × tint × (1 − F(0°)), F(0°) = ((η−1)/(η+1))².
TEST(RasterTransmission, ThinGlassShowsWhatLiesBehindTintedByItsBaseColour) {
  for (int msaa : {1, 4}) {
    Scene scene;
    const Rgb emitted(0.9f, 0.6f, 0.3f), tint(0.2f, 0.8f, 0.5f);
    MetallicRoughnessMaterial glass;
    glass.base_color = tint;
    glass.metallic = 0, glass.roughness = 0.5f;
    glass.transmission = 1;
    Material m;
    m.name = "glass";
    m.model = glass;
    m.double_sided = true;
    scene.materials = {label(emitted), m};
    // The glass is listed first: it must still be drawn after what it shows.
    scene.add_meshes({quad(1, 0.5f, 0.f), quad(0, 2.f, -1.f)});
    scene.camera.world_from_camera = world_from_camera_look_at({0, 0, 5}, {0, 0, 0});
    scene.camera.projection = Orthographic{2, 2};
    scene.camera.film.width_px = scene.camera.film.height_px = kSize;
    scene.camera.film.filter = BoxFilter{1e-6};
    RasterSettings settings;
    settings.msaa_samples = msaa;
    settings.surface_lights = false;
    SceneRasterizer rasterizer(scene, settings);
    Film film(kSize, kSize);
    rasterizer.render(scene.camera, film);
    Image color = film.to_image();
    const float exposure = float(scene.camera.exposure_scale());
    const float f0 = 0.04f;  // η = 1.5
    for (int y = 16; y < 32; ++y)
      for (int x = 16; x < 32; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(color.at(x, y, c), emitted[c] * tint[c] * (1 - f0) * exposure, 1e-4f)
              << x << ", " << y << " channel " << c << " msaa " << msaa;
    // Outside the glass the emitter is seen directly.
    EXPECT_NEAR(color.at(2, 2, 0), emitted.r * exposure, 1e-5f);
  }
}

}  // namespace
}  // namespace obscura::raster

// Obscura's JSON scene file: every example scene loads, the file's values arrive where they
// belong, mistakes are errors naming the file and the JSON path, and the Cornell box described
// in JSON (from the measured OBJ) renders like the one built in code.
#include "obscura/io/json_scene.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

class JsonScene : public testing::Test {
 protected:
  std::string dir = test::make_temp_dir("obscura-json");
  std::string write(const std::string& name, const std::string& text) {
    std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  void expect_error(const std::string& text, const std::vector<std::string>& fragments) {
    std::string path = write("scene.json", text);
    try {
      load_scene_file(path);
      ADD_FAILURE() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr("scene.json"));
      for (const std::string& f : fragments) EXPECT_THAT(e.what(), testing::HasSubstr(f));
    }
  }
};

TEST_F(JsonScene, EveryExampleSceneLoads) {
  int loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    Scene scene = load_scene_file(entry.path().string());
    EXPECT_GT(scene.stats().triangles, 0u) << entry.path();
    EXPECT_FALSE(scene.cameras.empty()) << entry.path();
    ++loaded;
  }
  EXPECT_GE(loaded, 6);
}

TEST_F(JsonScene, ValuesArriveWhereTheyBelong) {
  std::string path = write("values.json", R"({
    "render": {"width": 320, "height": 200, "spp": 9, "seed": 4},
    "materials": {
      "red": {"type": "diffuse", "reflectance": [0.5, 0.1, 0.1]},
      "glass": {"type": "dielectric", "ior": 1.33},
      "lamp": {"type": "emissive", "emission": [1, 2, 3], "emission_strength": 2}
    },
    "objects": [
      {"shape": "box", "size": [2, 4, 6], "material": "red",
       "transform": {"translate": [1, 2, 3], "rotate_degrees": [0, 90, 0], "scale": 0.5}},
      {"shape": "sphere", "radius": 1, "segments": 16, "material": "glass"},
      {"shape": "rectangle", "size": [1, 1], "material": "lamp"}
    ],
    "lights": [
      {"type": "spot", "position": [0, 5, 0], "target": [0, 0, 0], "intensity": 3,
       "inner_cone_degrees": 10, "outer_cone_degrees": 30}
    ],
    "cameras": [
      {"name": "a", "position": [0, 0, 10], "target": [0, 0, 0], "fov_degrees": 30},
      {"name": "b", "position": [0, 0, 10], "target": [0, 0, 0], "focal_length_mm": 50,
       "sensor_height_mm": 24, "f_number": 2.8, "focus_distance": 10}
    ],
    "camera": "b"
  })");
  Scene scene = load_scene_file(path);
  EXPECT_EQ(*scene.render.width, 320);
  EXPECT_EQ(*scene.render.samples_per_pixel, 9);
  EXPECT_EQ(*scene.render.seed, 4u);
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(std::get<DiffuseMaterial>(scene.materials[0].model).reflectance, Rgb(0.5f, 0.1f, 0.1f));
  EXPECT_FLOAT_EQ(std::get<DielectricMaterial>(scene.materials[1].model).ior, 1.33f);
  EXPECT_EQ(scene.materials[2].emission, Rgb(2, 4, 6));
  // The box (2 × 4 × 6, half scale, turned 90° about Y, moved to (1, 2, 3)) spans
  // x 1 ± 1.5, y 2 ± 1, z 3 ± 0.5.
  Bounds3f box = scene.meshes[0].bounds();
  Bounds3f world;
  for (Point3f p : scene.meshes[0].positions)
    world = unite(world, scene.instances[0].world_from_object(p));
  // Generated shapes share a unit mesh; the instance's transform gives the size.
  EXPECT_NEAR(box.diagonal().z, 1, 1e-6);
  EXPECT_NEAR(world.min.x, -0.5, 1e-5);
  EXPECT_NEAR(world.max.x, 2.5, 1e-5);
  EXPECT_NEAR(world.min.y, 1, 1e-5);
  EXPECT_NEAR(world.max.z, 3.5, 1e-5);
  const auto& spot = std::get<SpotLight>(scene.lights[0].model);
  EXPECT_NEAR(spot.direction.y, -1, 1e-6);
  EXPECT_NEAR(spot.outer_cone_radians, 30 * std::numbers::pi / 180, 1e-6);
  // "camera": "b" is the render camera: 50 mm on a 24 mm-high sensor.
  scene.camera.film.width_px = 360, scene.camera.film.height_px = 240;  // the sensor's 3:2
  // With the lens focused at 10 m the sensor sits at v = f·S/(S − f) = 50.2513 mm, so the
  // vertical FOV is 2·atan(12 / 50.2513) = 26.8614° (at infinity focus it would be 26.9915°).
  EXPECT_NEAR(scene.camera.fov_degrees().y, 26.861411, 1e-5);
  EXPECT_DOUBLE_EQ(std::get<Perspective>(scene.camera.projection).focal_length_mm, 50);
  EXPECT_EQ(scene.camera.name, "b");
  EXPECT_TRUE(scene.camera.lens.depth_of_field);
  EXPECT_DOUBLE_EQ(scene.camera.lens.f_number, 2.8);
  EXPECT_DOUBLE_EQ(scene.camera.lens.focus_distance_m, 10);
  EXPECT_FALSE(scene.cameras[0].lens.depth_of_field);
  EXPECT_NEAR(scene.cameras[0].fov_degrees().y, 30, 1e-9);
}

TEST_F(JsonScene, ModelsAreIncludedWithTheirTransformAndUpAxis) {
  std::string bunny = test::data_path("meshes/stanford_bunny/bun_zipper_res4.ply");
  std::string path = write("include.json", R"({
    "materials": {"clay": {"type": "diffuse"}},
    "objects": [
      {"name": "a", "model": ")" + bunny + R"(", "material": "clay", "transform": {"scale": 10}},
      {"name": "b", "model": ")" + bunny + R"(", "up": "z"}
    ]})");
  Scene scene = load_scene_file(path);
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.stats().triangles, 2 * 948u);  // README: res4 has 948 triangles
  Bounds3f a, b, original = scene.meshes[scene.instances[1].mesh].bounds();
  for (Point3f p : scene.meshes[0].positions) a = unite(a, scene.instances[0].world_from_object(p));
  for (Point3f p : scene.meshes[1].positions) b = unite(b, scene.instances[1].world_from_object(p));
  EXPECT_NEAR(a.diagonal().x, 10 * original.diagonal().x, 1e-4);
  // Z-up: the model's +Z becomes +Y, its +Y becomes −Z.
  EXPECT_NEAR(b.max.y, original.max.z, 1e-6);
  EXPECT_NEAR(b.min.z, -original.max.y, 1e-6);
  EXPECT_EQ(scene.material_of(scene.instances[0]), 0u);
}

TEST_F(JsonScene, MotionBlurSceneHasMovingObjectsAndCamera) {
  Scene scene = load_scene_file(test::source_path("scenes/motion-blur.json"));
  const Instance* ball = nullptr;
  for (const Instance& i : scene.instances)
    if (i.name == "ball") ball = &i;
  ASSERT_NE(ball, nullptr);
  ASSERT_EQ(ball->motion.size(), 2u);
  // The file: x from −1 at t = 0 to 0.2 at t = 1/30 s.
  EXPECT_NEAR(ball->motion[0].world_from_object(Point3d(0, 0, 0)).x, -1, 1e-9);
  EXPECT_NEAR(ball->motion[1].world_from_object(Point3d(0, 0, 0)).x, 0.2, 1e-9);
  EXPECT_NEAR(ball->motion[1].time_seconds, 0.0333333, 1e-9);
  ASSERT_EQ(scene.cameras.size(), 1u);
  EXPECT_TRUE(scene.cameras[0].world_from_camera.is_animated());
  EXPECT_EQ(scene.cameras[0].world_from_camera.keys().size(), 2u);
  EXPECT_NEAR(scene.cameras[0].shutter.close_s, 0.0333333, 1e-9);
  // The camera moves from x = 0 to x = −0.2 during the exposure.
  EXPECT_NEAR(scene.camera.world_from_camera.at(0.0333333)(Point3d(0, 0, 0)).x, -0.2, 1e-9);
}

TEST_F(JsonScene, UnknownKeyNamesTheKeyAndItsPath) {
  expect_error(R"({"materials": {"red": {"type": "diffuse", "reflectanse": 0.5}}})",
               {"$.materials.red.reflectanse", "unknown key 'reflectanse'"});
  expect_error(
      R"({"objects": [{"shape": "sphere", "material": "m", "radius": 1}], "materials": {"m": {"type": "diffuse"}}, "camras": []})",
      {"$.camras"});
  expect_error(R"({"cameras": [{"position": [0, 0, 1], "fov": 40}]})", {"$.cameras[0].fov"});
}

TEST_F(JsonScene, VignettingAndGlareArriveWhereTheyBelong) {
  Scene scene = load_scene_file(write("scene.json", R"({
    "render": {"glare": 2.5, "glare_radius": 64},
    "cameras": [{"f_number": 2, "vignetting": {"natural": true, "barrel_diameter_mm": 30,
                                               "barrel_distance_mm": 40}}]})"));
  EXPECT_EQ(scene.render.glare_strength, 2.5);
  EXPECT_EQ(scene.render.glare_radius_px, 64);
  EXPECT_TRUE(scene.camera.lens.vignetting.natural);
  EXPECT_EQ(scene.camera.lens.vignetting.barrel_diameter_mm, 30);
  EXPECT_EQ(scene.camera.lens.vignetting.barrel_distance_mm, 40);
  expect_error(R"({"cameras": [{"vignetting": {"natural": true, "barel_diameter_mm": 3}}]})",
               {"$.cameras[0].vignetting.barel_diameter_mm"});
  expect_error(R"({"render": {"glare": -1}})", {"$.render.glare"});
  // 50 mm f/2 is a 25 mm aperture: a 20 mm barrel would be the aperture.
  expect_error(R"({"cameras": [{"f_number": 2, "vignetting": {"barrel_diameter_mm": 20}}]})",
               {"barrel_diameter_mm", "aperture diameter"});
}

TEST_F(JsonScene, MalformedJsonGivesLineAndColumn) {
  expect_error("{\n  \"name\": \"x\",\n  \"objects\": [,]\n}", {"scene.json:3:", "malformed JSON"});
}

TEST_F(JsonScene, UnknownMaterialType) {
  expect_error(R"({"materials": {"m": {"type": "velvet"}}})",
               {"$.materials.m.type", "unknown material type 'velvet'", "metallic-roughness"});
}

TEST_F(JsonScene, WrongTypesAndRanges) {
  expect_error(R"({"materials": {"m": {"type": "dielectric", "ior": "glass"}}})",
               {"$.materials.m.ior", "expected a number"});
  expect_error(R"({"materials": {"m": {"type": "conductor", "roughness": 2}}})",
               {"$.materials.m.roughness", "[0, 1]"});
  expect_error(R"({"objects": [{"shape": "sphere", "material": "nope"}]})",
               {"$.objects[0].material", "no material named 'nope'"});
  expect_error(
      R"({"objects": [{"shape": "mesh", "positions": [0,0,0, 1,0,0, 0,1,0], "indices": [0,1,3]}], "materials": {}})",
      {"$.objects[0]", "past the vertex count 3"});
  expect_error(R"({"camera": "missing", "cameras": [{"name": "a"}]})",
               {"no camera named 'missing'"});
}

// An analytic sphere keeps its centre and radius: one shared unit sphere (its tessellation for
// the tracer and the rasterizer, and the sphere itself), placed by the instance.
TEST_F(JsonScene, AnalyticSphereKeepsItsCentreAndRadius) {
  std::string path = write("analytic.json", R"({
    "materials": {"m": {"type": "diffuse"}},
    "objects": [
      {"shape": "analytic_sphere", "center": [1, 2, 3], "radius": 0.5, "material": "m"},
      {"shape": "analytic_sphere", "radius": 2, "segments": 8, "material": "m"}
    ]})");
  const Scene scene = load_scene_file(path);
  ASSERT_EQ(scene.instances.size(), 2u);
  const Mesh& mesh = scene.meshes[scene.instances[0].mesh];
  ASSERT_TRUE(mesh.analytic_sphere.has_value());
  EXPECT_EQ(mesh.triangle_count(), 64u * 32u * 2u - 2u * 64u);  // 64 segments, poles as fans
  // The unit sphere's pole and a point on its equator land on the sphere of the file.
  const Transform& t = scene.instances[0].world_from_object;
  const Point3d pole = t(Point3d(0, 1, 0)), side = t(Point3d(1, 0, 0));
  EXPECT_NEAR(pole.x, 1, 1e-12);
  EXPECT_NEAR(pole.y, 2.5, 1e-12);
  EXPECT_NEAR(pole.z, 3, 1e-12);
  EXPECT_NEAR(side.x, 1.5, 1e-12);
  EXPECT_NEAR(side.y, 2, 1e-12);
  const Mesh& coarse = scene.meshes[scene.instances[1].mesh];
  EXPECT_EQ(coarse.triangle_count(), 8u * 4u * 2u - 2u * 8u);
  EXPECT_NEAR(scene.instances[1].world_from_object(Point3d(0, 0, 1)).z, 2, 1e-12);
  expect_error(R"({"materials": {"m": {"type": "diffuse"}},
                   "objects": [{"shape": "analytic_sphere", "radius": 0, "material": "m"}]})",
               {"$.objects[0].radius"});
  expect_error(R"({"materials": {"m": {"type": "diffuse"}},
                   "objects": [{"shape": "analytic_sphere", "center": [0, 1e300, 0], "material": "m"}]})",
               {"$.objects[0].center"});
  expect_error(R"({"materials": {"m": {"type": "diffuse"}},
                   "objects": [{"shape": "analytic_sphere", "center": [0, 1], "material": "m"}]})",
               {"$.objects[0].center"});
}

TEST_F(JsonScene, SpectralFieldsArriveAndAreChecked) {
  // A dispersive glass, a blackbody lamp (its RGB: the colour of 6504 K, luminance 2) and the
  // render block's spectral switch.
  std::string path = write("spectral.json", R"({
    "render": {"spectral": true},
    "materials": {
      "flint": {"type": "dielectric", "ior": 1.78, "abbe_number": 25.8},
      "lamp": {"type": "emissive", "emission_kelvin": 6504, "emission_strength": 2}
    }})");
  Scene scene = load_scene_file(path);
  EXPECT_EQ(scene.render.spectral, true);
  const auto& flint = std::get<DielectricMaterial>(scene.materials[0].model);
  EXPECT_FLOAT_EQ(flint.abbe_number, 25.8f);
  EXPECT_FLOAT_EQ(scene.materials[1].emission_kelvin, 6504.f);
  Rgb lamp = scene.materials[1].emission;
  EXPECT_NEAR(0.2126729f * lamp.r + 0.7151522f * lamp.g + 0.0721750f * lamp.b, 2.f, 1e-3f);
  EXPECT_NEAR(lamp.r / lamp.b, 1.f, 0.1f);  // 6504 K is near D65, a neutral white
  expect_error(R"({"materials": {"m": {"type": "dielectric", "abbe_number": 0.5}}})",
               {"$.materials.m.abbe_number", "Abbe number"});
  expect_error(R"({"materials": {"m": {"type": "emissive", "emission": [1, 1, 1],
                   "emission_kelvin": 3000}}})",
               {"$.materials.m.emission_kelvin", "either"});
  expect_error(R"({"materials": {"m": {"type": "emissive", "emission_kelvin": 100}}})",
               {"$.materials.m.emission_kelvin"});
  expect_error(R"({"render": {"spectral": "yes"}})", {"$.render.spectral"});
}

TEST_F(JsonScene, MissingTextureAndMissingModel) {
  expect_error(R"({"materials": {"m": {"type": "diffuse", "reflectance_texture": "nowhere.png"}}})",
               {"$.materials.m.reflectance_texture", "nowhere.png", "does not exist"});
  expect_error(R"({"objects": [{"model": "nowhere.obj"}]})", {"nowhere.obj", "does not exist"});
}

TEST_F(JsonScene, MissingFile) {
  try {
    load_scene_file(dir + "/absent.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr("absent.json"));
  }
}

// The round trip: the Cornell box built in code and the same box described in JSON (the
// measured OBJ, scaled from millimetres) render the same picture.
Image render_small(const Scene& scene_in) {
  Scene scene = scene_in;
  scene.camera.film.width_px = scene.camera.film.height_px = 48;
  auto device = std::make_shared<EmbreeDevice>();
  TraceScene trace(scene, device);
  Film film(48, 48);
  render(trace, scene.camera, DirectLightingIntegrator(),
         {.samples_per_pixel = 16, .seed = 7, .tile_size = 16}, film);
  return film.to_image();
}

TEST(JsonSceneRoundTrip, CornellBoxFromJsonRendersLikeTheOneBuiltInCode) {
  Scene code = make_cornell_box();
  Scene json = load_scene_file(test::source_path("scenes/cornell-box.json"));
  EXPECT_EQ(code.stats().triangles, json.stats().triangles);
  Bounds3f a = code.bounds(), b = json.bounds();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(a.min[k], b.min[k], 1e-6);
    EXPECT_NEAR(a.max[k], b.max[k], 1e-6);
  }
  Image x = render_small(code), y = render_small(json);
  ASSERT_EQ(x.data.size(), y.data.size());
  // Vertices differ by float rounding (mm × 0.001 in float vs in double), so a handful of
  // samples may land on the other side of an edge; everything else is the same number.
  size_t different = 0;
  double sum_x = 0, sum_y = 0;
  for (size_t i = 0; i < x.data.size(); ++i) {
    different += std::abs(x.data[i] - y.data[i]) > 1e-5f * std::max(1.f, std::abs(x.data[i]));
    sum_x += x.data[i], sum_y += y.data[i];
  }
  EXPECT_LE(different, x.data.size() / 100);
  EXPECT_NEAR(sum_x / sum_y, 1, 1e-3);
}

}  // namespace
}  // namespace obscura

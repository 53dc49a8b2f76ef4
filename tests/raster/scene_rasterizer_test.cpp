// The scene rasterizer against the tracer (an independent renderer of the same scene: Embree ray
// casts, the trace/ BSDFs) and against radiometry known in closed form.
#include "obscura/raster/scene_rasterizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "obscura/camera/frames.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/scene/builtin_scenes.h"
#include "obscura/scene/shapes.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "raster_images.h"
#include "test_paths.h"

namespace obscura::raster {
namespace {

// A box filter this narrow puts every tracer sample at its pixel centre, where the rasterizer
// samples too.
constexpr double kCentreOnly = 1e-6;

Camera with_film(Camera camera, int width, int height) {
  camera.film.width_px = width;
  camera.film.height_px = height;
  camera.film.filter = BoxFilter{kCentreOnly};
  return camera;
}

// The tracer's id and colour AOVs (one sample at each pixel centre, direct light).
struct TracerImages {
  Image color, id;
};
TracerImages trace(const Scene& scene, const Camera& camera) {
  TraceScene trace_scene(scene, std::make_shared<EmbreeDevice>());
  Bounds2i crop = camera.film.crop_pixels();
  Film film(crop.width(), crop.height());
  AovBuffers aovs(crop.width(), crop.height());
  render(trace_scene, camera, DirectLightingIntegrator(), {.samples_per_pixel = 1, .seed = 1}, film,
         {}, &aovs);
  return {film.to_image(), aovs.id()};
}

using test_images::on_silhouette;
using test_images::RasterImages;
test_images::RasterImages rasterize(const Scene& scene, const Camera& camera,
                                    RasterSettings settings = {}) {
  return test_images::rasterize_with_aovs(scene, camera, settings);
}

Scene example_scene(const std::string& name) {
  if (name == "cornell-box") return make_builtin_scene(name);
  return load_scene_file(test::source_path("scenes/" + name + ".json"));
}

class ExampleScene : public ::testing::TestWithParam<const char*> {};

TEST_P(ExampleScene, ObjectIdsAgreeWithTheTracerAtPixelCentres) {
  Scene scene = example_scene(GetParam());
  Camera camera = with_film(scene.camera, 160, 120);
  TracerImages traced = trace(scene, camera);
  RasterImages raster = rasterize(scene, camera);
  int agree = 0, total = camera.film.width_px * camera.film.height_px, off_silhouette = 0;
  int objects_seen = 0;
  for (int y = 0; y < camera.film.height_px; ++y)
    for (int x = 0; x < camera.film.width_px; ++x) {
      if (traced.id.at(x, y, 0) == raster.id.at(x, y, 0)) {
        ++agree;
        objects_seen += traced.id.at(x, y, 0) >= 0;
      } else if (!on_silhouette(traced.id, x, y)) {
        ++off_silhouette;
        ADD_FAILURE() << GetParam() << ": pixel (" << x << ", " << y << ") is id "
                      << raster.id.at(x, y, 0) << " in the raster, " << traced.id.at(x, y, 0)
                      << " in the tracer, away from any silhouette";
      }
    }
  EXPECT_GE(double(agree) / total, 0.999) << GetParam() << ": " << total - agree << " differ";
  EXPECT_EQ(off_silhouette, 0);
  EXPECT_GT(objects_seen, total / 5);  // the comparison is not over an empty frame
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleScene,
                         ::testing::Values("cornell-box", "spheres-and-lights", "bunny",
                                           "gltf-spheres"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

Material material(const char* name, MaterialModel model) {
  Material m;
  m.name = name;
  m.model = model;
  return m;
}
Material diffuse(const char* name, Rgb reflectance) {
  DiffuseMaterial d;
  d.reflectance = reflectance;
  return material(name, d);
}
RasterSettings with_msaa(int samples) {
  RasterSettings s;
  s.msaa_samples = samples;
  return s;
}

// Three spheres (Lambert, Phong, metallic-roughness) under a point, a spot and a directional
// light, placed so that no sphere shadows another: the tracer's direct light (with shadow rays)
// is then exactly what the rasterizer computes (without them).
Scene direct_light_scene(bool blinn) {
  Scene scene;
  scene.name = "direct-light";
  obscura::PhongMaterial phong;
  phong.diffuse = Rgb(0.2f, 0.4f, 0.6f);
  phong.specular = Rgb(0.3f);
  phong.shininess = 24;
  phong.blinn = blinn;
  MetallicRoughnessMaterial gltf;
  gltf.base_color = Rgb(0.9f, 0.6f, 0.2f);
  gltf.metallic = 0.4f;
  gltf.roughness = 0.45f;
  scene.materials = {diffuse("lambert", Rgb(0.7f, 0.5f, 0.3f)), material("phong", phong),
                     material("gltf", gltf)};
  for (int i = 0; i < 3; ++i) {
    Mesh sphere = make_sphere(0.5f, 128);
    sphere.material = uint32_t(i);
    scene.add_mesh(std::move(sphere), Transform::translate({-1.5 + 1.5 * i, 0, 0}));
  }
  scene.lights = {
      {"bulb", obscura::PointLight{.position = {0, 3, 3}, .intensity = Rgb(12.f)}},
      {"spot", obscura::SpotLight{.position = {-2, 2, 4},
                                  .direction = normalize(Vector3f(0.5f, -2, -4)),
                                  .intensity = Rgb(30.f, 25.f, 20.f),
                                  .inner_cone_radians = 0.2f,
                                  .outer_cone_radians = 0.5f}},
      {"sun", obscura::DirectionalLight{.direction = normalize(Vector3f(-0.3f, -1, -0.6f)),
                                        .irradiance = Rgb(1.5f)}}};
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0.8, 5}, {0, 0, 0});
  scene.camera.projection = Perspective::from_horizontal_fov_degrees(50);
  return scene;
}

void expect_direct_light_agrees(const Scene& scene, RasterSettings settings,
                                double max_relative_bound = 0.02,
                                double mean_relative_bound = 1e-3) {
  Camera camera = with_film(scene.camera, 200, 100);
  TracerImages traced = trace(scene, camera);
  RasterImages raster = rasterize(scene, camera, settings);
  // Relative where lit, absolute (against a tenth of the typical level) in the dark.
  test_images::ColourAgreement a =
      test_images::compare_colours(traced.color, traced.id, raster.color, raster.id);
  ASSERT_GT(a.compared, 3000);
  for (int i = 0; i < 3; ++i) EXPECT_GT(a.lit[i], 300) << "sphere " << i << " is hardly lit";
  EXPECT_LT(a.mean_relative, mean_relative_bound);
  EXPECT_LT(a.max_relative, max_relative_bound);
}

// Shading alone: no sphere shadows another, and the rasterizer draws without shadow maps (their
// filtering softens the terminator slightly; shadows are compared below).
RasterSettings unshadowed(int msaa) {
  RasterSettings s = with_msaa(msaa);
  s.shadow_map_size = 0;
  return s;
}

TEST(SceneRasterizer, DirectLightAgreesWithTheTracersDirectLighting) {
  expect_direct_light_agrees(direct_light_scene(false), unshadowed(1));
  expect_direct_light_agrees(direct_light_scene(true), unshadowed(1));
}

TEST(SceneRasterizer, DirectLightAgreesWithMultisampling) {
  // MSAA shades each triangle covering a sample once, at the pixel centre, and averages the
  // samples: where a pixel straddles facets near a light's terminator (where one facet's plane
  // already hides the light and the next does not) the average departs from the single centre
  // sample by up to ~15 % of a dim value; everywhere else nothing changes. Those pixels raise
  // the mean difference to ~1.1e-3 (the Lambert sphere's terminator alone gives 0.46e-3; the
  // metallic-roughness sphere's diffuse-like multiple scattering 0.35e-3).
  expect_direct_light_agrees(direct_light_scene(false), unshadowed(4), 0.2, 1.5e-3);
}

TEST(SceneRasterizer, ShadowMapsCastTheShadowsTheTracerCasts) {
  // The spheres on a floor, lit by the directional and the spot light (the point light would
  // need a cube map): the floor's shadows against the tracer's shadow rays.
  Scene scene = direct_light_scene(false);
  scene.lights.erase(scene.lights.begin());  // the point light
  scene.materials.push_back(diffuse("floor", Rgb(0.6f)));
  Mesh floor = make_rectangle(12, 8);
  floor.material = 3;
  scene.add_mesh(std::move(floor), Transform::translate({0, -0.5, 0}));
  Camera camera = with_film(scene.camera, 200, 100);
  camera.world_from_camera = world_from_camera_look_at({0, 3, 5}, {0, -0.5, 0});
  TracerImages traced = trace(scene, camera);
  RasterImages raster = rasterize(scene, camera);
  int floor_pixels = 0, agree = 0, shadowed = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 200; ++x) {
      if (traced.id.at(x, y, 0) != 3 || raster.id.at(x, y, 0) != 3 ||
          on_silhouette(traced.id, x, y))
        continue;
      ++floor_pixels;
      double t = traced.color.at(x, y, 1), r = raster.color.at(x, y, 1);
      agree += std::abs(r - t) <= 0.02 * std::max(t, 0.05);
      shadowed += t < 0.5 * raster.color.at(10, 99, 1);  // darker than the open floor's half
    }
  ASSERT_GT(floor_pixels, 5000);
  EXPECT_GT(shadowed, 300) << "the test must see shadows";
  // Shadow edges: the map's texels and 3×3 filtering blur them over about a pixel.
  EXPECT_GT(double(agree) / floor_pixels, 0.97);
}

TEST(SceneRasterizer, ConvexLambertianObjectInAUniformSurroundReflectsAlbedoTimesRadiance) {
  // A uniform environment of radiance L around an unoccluded convex Lambertian surface: every
  // point receives E = πL and reflects ρE/π = ρL; the background shows L. Exposure applies.
  Scene scene;
  scene.materials = {diffuse("grey", Rgb(0.25f, 0.5f, 0.75f))};
  scene.add_mesh(make_sphere(1, 64));
  scene.environment = Environment();
  scene.environment->color = Rgb(0.8f);
  scene.environment->intensity = 2;
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0, 4}, {0, 0, 0});
  scene.camera.exposure.compensation_ev = 1;
  Camera camera = with_film(scene.camera, 64, 64);
  const float exposure = float(camera.exposure_scale());
  RasterImages raster = rasterize(scene, camera);
  EXPECT_NEAR(raster.color.at(32, 32, 0), 0.25f * 1.6f * exposure, 1e-5);
  EXPECT_NEAR(raster.color.at(32, 32, 2), 0.75f * 1.6f * exposure, 1e-5);
  EXPECT_NEAR(raster.color.at(0, 0, 1), 1.6f * exposure, 1e-5);
}

TEST(SceneRasterizer, EmittersShowTheirRadianceFromTheFrontOnly) {
  Scene scene;
  Material lamp = material("lamp", EmissiveMaterial{});
  lamp.emission = Rgb(3, 2, 1);
  scene.materials = {lamp};
  scene.add_mesh(make_rectangle(1, 1), Transform::translate({-0.7, 0, 0}) *
                                           Transform::rotate_x(std::numbers::pi / 2));  // faces +Z
  scene.add_mesh(make_rectangle(1, 1), Transform::translate({0.7, 0, 0}) *
                                           Transform::rotate_x(-std::numbers::pi / 2));  // faces −Z
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0, 4}, {0, 0, 0});
  Camera camera = with_film(scene.camera, 64, 32);
  RasterSettings no_lights;
  no_lights.surface_lights = false;
  RasterImages raster = rasterize(scene, camera, no_lights);
  float e = float(camera.exposure_scale());
  EXPECT_EQ(raster.id.at(16, 16, 0), 0);
  EXPECT_EQ(raster.id.at(48, 16, 0), 1);
  EXPECT_NEAR(raster.color.at(16, 16, 0), 3 * e, 1e-5);
  EXPECT_NEAR(raster.color.at(16, 16, 2), 1 * e, 1e-5);
  EXPECT_EQ(raster.color.at(48, 16, 0), 0.f);
}

TEST(SceneRasterizer, FrameTakesExplicitMatricesAndTheShutterTime) {
  Scene scene;
  scene.materials = {diffuse("white", Rgb(1.f))};
  scene.add_mesh(make_sphere(0.25f, 32));
  // The sphere moves 1 m along +X between t = 0 and t = 1.
  scene.instances[0].motion = {{0, Transform()}, {1, Transform::translate({1, 0, 0})}};
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0, 5}, {0, 0, 0});
  Camera camera = with_film(scene.camera, 96, 64);
  RasterSettings settings;
  settings.aovs = true;
  SceneRasterizer rasterizer(scene, settings);
  RenderTarget target = rasterizer.make_target(camera);

  auto centre_of_object = [&](double t, const RasterFrame& frame) {
    rasterizer.render_frame(camera, frame, target);
    double sum_x = 0;
    int n = 0;
    for (int y = 0; y < target.height(); ++y)
      for (int x = 0; x < target.width(); ++x)
        if (target.object_id_at(x, y) == 1) sum_x += x + 0.5, ++n;
    EXPECT_GT(n, 20) << "t = " << t;
    return sum_x / std::max(n, 1);
  };
  double at_start = 0;
  for (double t : {0.0, 0.5, 1.0}) {
    RasterFrame frame;
    frame.time_s = t;
    // Where the camera itself projects the moving centre (a sphere off the axis projects to an
    // ellipse whose centroid lies a little farther out: a quarter pixel here).
    double expected = camera.project({t, 0, 0})->film_point.x;
    double centre = centre_of_object(t, frame);
    EXPECT_NEAR(centre, expected, 0.25) << "t = " << t;
    if (t == 0) at_start = centre;
  }
  // A view matrix given explicitly replaces the camera's: the camera moved 1 m to the right
  // sees the sphere at t = 1 where the fixed camera saw it at t = 0.
  RasterFrame shifted;
  shifted.time_s = 1;
  shifted.view = camera.view_matrix() * Transform::translate({-1, 0, 0}).matrix();
  shifted.projection = camera.projection_matrix();
  EXPECT_NEAR(centre_of_object(1, shifted), at_start, 0.05);
}

TEST(SceneRasterizer, CropWindowRendersThatPartOfTheFullImage) {
  Scene scene = direct_light_scene(false);
  Camera full = with_film(scene.camera, 120, 60);
  Camera cropped = full;
  cropped.film.crop = {.x_min = 0.25, .y_min = 0.5, .x_max = 0.75, .y_max = 1};
  RasterImages a = rasterize(scene, full), b = rasterize(scene, cropped);
  Bounds2i crop = cropped.film.crop_pixels();
  ASSERT_EQ(b.color.width, crop.width());
  int differ = 0;
  for (int y = 0; y < b.color.height; ++y)
    for (int x = 0; x < b.color.width; ++x) {
      differ += a.id.at(x + crop.min.x, y + crop.min.y, 0) != b.id.at(x, y, 0);
      if (a.id.at(x + crop.min.x, y + crop.min.y, 0) == b.id.at(x, y, 0)) {
        EXPECT_NEAR(a.color.at(x + crop.min.x, y + crop.min.y, 1), b.color.at(x, y, 1), 1e-4);
      }
    }
  EXPECT_LE(differ, 2);  // the shifted projection may round a silhouette pixel differently
}

TEST(SceneRasterizer, RejectsBadSampleCounts) {
  Scene scene = direct_light_scene(false);
  EXPECT_THROW({ SceneRasterizer rasterizer(scene, with_msaa(2)); }, Error);
}

}  // namespace
}  // namespace obscura::raster

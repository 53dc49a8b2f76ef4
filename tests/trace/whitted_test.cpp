#include "obscura/trace/whitted.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/shading/fresnel.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

std::shared_ptr<EmbreeDevice> device() {
  return testing::embree_device();
}

// The radiance through the centre of a 1-pixel, narrow camera.
Rgb centre_radiance(const TraceScene& scene, Point3d eye, Point3d target,
                    const Integrator& integrator, int spp = 1) {
  Camera camera = testing::make_camera(eye, target, 1, 0.01);
  Film film(1, 1);
  render(scene, camera, integrator, {.samples_per_pixel = spp}, film);
  return film.pixel({0, 0});
}

// An emitter of radiance 1 facing down at y = 2, 2s wide, over a floor at y = 0.
Scene sky_over_floor(float s = 100) {
  Scene scene;
  scene.name = "sky";
  scene.materials = {diffuse_material("floor", Rgb(0.5f)),
                     diffuse_material("sky", Rgb(0.f), Rgb(1.f))};
  scene.add_meshes({testing::make_quad("floor", 0, {-s, 0, -s}, {-s, 0, s}, {s, 0, s}, {s, 0, -s}),
                    testing::make_quad("sky", 1, {-s, 2, -s}, {s, 2, -s}, {s, 2, s}, {-s, 2, s})});
  return scene;
}

TEST(Whitted, MirrorReflectsTheLightItSeesWeightedByFresnel) {
  Rgb eta(0.2f, 0.92f, 1.1f), k(3.9f, 2.45f, 2.14f);
  TraceScene scene(sky_over_floor(), device());
  scene.set_material(0, TraceMaterial(ConductorBsdf(eta, k, 0)));
  // Looking down at 45°: the mirror shows the sky through F(cos 45°).
  Rgb expected = shading::fresnel_conductor(std::sqrt(0.5f), eta, k);
  Rgb whitted = centre_radiance(scene, {0, 1, 1}, {0, 0, 0}, WhittedIntegrator());
  Rgb path = centre_radiance(scene, {0, 1, 1}, {0, 0, 0}, PathTracer());
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(whitted[c], expected[c], 1e-3f);
    EXPECT_NEAR(path[c], expected[c], 1e-3f);
  }
}

TEST(Whitted, GlassSlabTransmitsWhatFresnelLeaves) {
  // Looking straight up through a glass slab (n = 1.5) at the sky: light crosses two interfaces
  // and bounces between them, T = (1 − R)² Σ R^2k = (1 − R)/(1 + R) with R = 0.04 → 0.9231.
  // The 1/η² radiance scaling on entry is undone on exit.
  Scene scene = sky_over_floor();
  scene.materials.push_back(diffuse_material("glass", Rgb(0.f)));
  const float s = 100;
  scene.add_mesh(testing::make_quad("slab top", 2, {-s, 1.2f, -s}, {-s, 1.2f, s}, {s, 1.2f, s},
                                    {s, 1.2f, -s}));
  scene.add_mesh(
      testing::make_quad("slab bottom", 2, {-s, 1, -s}, {s, 1, -s}, {s, 1, s}, {-s, 1, s}));
  TraceScene trace_scene(scene, device());
  trace_scene.set_material(2, TraceMaterial(DielectricBsdf(1.5f, 0)));
  trace_scene.set_material(0, TraceMaterial(LambertianBsdf{Rgb(0.f)}));  // no light from below
  float r = shading::fresnel_f0(1.5f), expected = (1 - r) / (1 + r);
  Rgb whitted = centre_radiance(trace_scene, {0, 0.5, 0}, {0, 2, 0.0001}, WhittedIntegrator());
  EXPECT_NEAR(whitted.g, expected, 1e-3f);
  // The path tracer picks one branch per interface at random; on average the same.
  Rgb path = centre_radiance(trace_scene, {0, 0.5, 0}, {0, 2, 0.0001}, PathTracer(), 4096);
  EXPECT_NEAR(path.g, expected, 0.01f);
}

TEST(Whitted, DeepMirrorCorridorNeedsNoStack) {
  // Two facing mirrors and a ray along their normal: every bounce continues, so the ray tree is
  // one chain, as deep as max_depth allows. Asked for 200,000 levels (recursion overflowed the
  // stack long before), the chain ends at the ray budget and sees no light (there is none between
  // the mirrors).
  Scene scene = sky_over_floor();
  scene.materials.push_back(diffuse_material("mirror", Rgb(0.f)));
  scene.add_mesh(testing::make_quad("left", 2, {-1, 0, -5}, {-1, 2, -5}, {-1, 2, 5}, {-1, 0, 5}));
  scene.add_mesh(testing::make_quad("right", 2, {1, 0, -5}, {1, 0, 5}, {1, 2, 5}, {1, 2, -5}));
  TraceScene trace_scene(scene, device());
  trace_scene.set_material(2, TraceMaterial(ConductorBsdf(Rgb(0.2f), Rgb(3.9f), 0)));
  WhittedIntegrator deep(WhittedSettings{.max_depth = 200000});
  Camera camera = testing::make_camera({0, 1, 0}, {1, 1, 0}, 1, 0.01);
  Film film(1, 1);
  RenderStats stats = render(trace_scene, camera, deep, {.samples_per_pixel = 1}, film);
  EXPECT_EQ(stats.rays.camera + stats.rays.bounce, uint64_t(WhittedIntegrator::kRayBudget));
  Rgb seen = film.pixel({0, 0});
  EXPECT_TRUE(std::isfinite(seen.g));
  EXPECT_LT(seen.g, 1e-3f);
}

TEST(Whitted, GlassAtDepth1024StaysWithinTheRayBudget) {
  // Every glass interface splits the ray in two; at depth 1024 recursion would trace 2^1024 rays.
  // The budget caps a camera ray's tree at kRayBudget rays, and what it drops is light reflected
  // back and forth a dozen times (R^12 ~ 1e-17). The slab transmits T = (1 − R)/(1 + R) and
  // reflects Rs = 2R/(1 + R); the glass floor returns R of what comes down, so the sky arrives as
  // T (1 + Rs R + (Rs R)^2 + …) = T / (1 − Rs R) = 25/27 for R = 0.04.
  Scene scene = sky_over_floor();
  scene.materials.push_back(diffuse_material("glass", Rgb(0.f)));
  const float s = 100;
  scene.add_mesh(testing::make_quad("slab top", 2, {-s, 1.2f, -s}, {-s, 1.2f, s}, {s, 1.2f, s},
                                    {s, 1.2f, -s}));
  scene.add_mesh(
      testing::make_quad("slab bottom", 2, {-s, 1, -s}, {s, 1, -s}, {s, 1, s}, {-s, 1, s}));
  TraceScene trace_scene(scene, device());
  trace_scene.set_material(2, TraceMaterial(DielectricBsdf(1.5f, 0)));
  trace_scene.set_material(0, TraceMaterial(DielectricBsdf(1.5f, 0)));  // glass floor too
  Camera camera = testing::make_camera({0, 0.5, 0}, {0, 2, 0.0001}, 1, 0.01);
  Film film(1, 1);
  RenderStats stats = render(trace_scene, camera, WhittedIntegrator({.max_depth = 1024}),
                             {.samples_per_pixel = 1}, film);
  EXPECT_LE(stats.rays.camera + stats.rays.bounce, uint64_t(WhittedIntegrator::kRayBudget));
  float r = shading::fresnel_f0(1.5f), t = (1 - r) / (1 + r), rs = 2 * r / (1 + r);
  EXPECT_NEAR(film.pixel({0, 0}).g, t / (1 - rs * r), 1e-3f);
}

TEST(Whitted, DiffuseSurfacesGetDirectLightWithShadows) {
  // The floor's centre under a square emitter of half-width a at height h: radiance ρ·L·F with
  // the form factor F = 4·F_corner(a/h, a/h) (the closed form for a parallel rectangle, e.g.
  // Howell's catalogue). The sky does not reflect, so there is no interreflection.
  auto corner = [](double x, double y) {
    double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * std::numbers::pi);
  };
  const float a = 3;
  TraceScene scene(sky_over_floor(a), device());
  double expected = 0.5 * 4 * corner(a / 2.0, a / 2.0);
  Rgb whitted = centre_radiance(scene, {0, 1, 0.5}, {0, 0, 0}, WhittedIntegrator(), 8192);
  EXPECT_NEAR(whitted.g, expected, 0.01 * expected);
  Rgb path = centre_radiance(scene, {0, 1, 0.5}, {0, 0, 0}, PathTracer(), 8192);
  EXPECT_NEAR(path.g, expected, 0.01 * expected);
}

TEST(Aovs, FirstHitAlbedoNormalDepthAndId) {
  TraceScene scene(sky_over_floor(), device());
  Camera camera = testing::make_camera({0, 1, 0.001}, {0, 0, 0}, 4, 10);  // looking down
  Film film(4, 4);
  AovBuffers aovs(4, 4);
  render(scene, camera, WhittedIntegrator(), {.samples_per_pixel = 4}, film, {}, &aovs);
  Image albedo = aovs.albedo(), normal = aovs.normal(), depth = aovs.depth(), id = aovs.id();
  EXPECT_NEAR(albedo.at(1, 1, 0), 0.5f, 1e-6f);
  EXPECT_NEAR(normal.at(1, 1, 1), 1.f, 1e-4f);  // the floor faces up, towards the camera
  EXPECT_NEAR(depth.at(1, 1, 0), 1.f, 0.01f);   // 1 m below the camera, nearly straight down
  EXPECT_EQ(id.at(1, 1, 0), 0.f);               // mesh 0: the floor
}

}  // namespace
}  // namespace obscura

namespace obscura {
namespace {

// A floor at y = 0 (albedo 0.5) and nothing else.
TraceScene lone_floor() {
  Scene scene;
  scene.name = "floor";
  scene.materials = {diffuse_material("floor", Rgb(0.5f))};
  const float s = 100;
  scene.add_meshes(
      {testing::make_quad("floor", 0, {-s, 0, -s}, {-s, 0, s}, {s, 0, s}, {s, 0, -s})});
  return TraceScene(scene, device());
}

TEST(PunctualLights, PointSpotAndDirectionalIlluminateByTheInverseSquareAndCosineLaws) {
  // Radiance of a Lambertian floor: ρ/π · E, E = I·cos θ/d² (point) or E·cos θ (directional).
  const double rho_over_pi = 0.5 / std::numbers::pi;
  TraceScene scene = lone_floor();
  // A point light 2 m up and 1 m aside of the looked-at point: cos θ = 2/√5, d² = 5.
  scene.set_punctual_lights({PunctualLight::point({1, 2, 0}, Rgb(10.f))});
  for (const Integrator* integrator :
       std::initializer_list<const Integrator*>{new WhittedIntegrator(), new PathTracer()}) {
    Rgb L = centre_radiance(scene, {0, 1, 0.001}, {0, 0, 0}, *integrator);
    EXPECT_NEAR(L.g, rho_over_pi * 10 * (2 / std::sqrt(5.0)) / 5, 1e-4);
    delete integrator;
  }
  // The sun from 60° off the zenith: E·cos 60°.
  scene.set_punctual_lights(
      {PunctualLight::directional(normalize(Vector3f(0, -0.5f, -0.8660254f)), Rgb(3.f))});
  EXPECT_NEAR(centre_radiance(scene, {0, 1, 0.001}, {0, 0, 0}, WhittedIntegrator()).g,
              rho_over_pi * 3 * 0.5, 1e-4);
  // A spot straight down: full inside its inner cone, dark outside the outer one.
  scene.set_punctual_lights({PunctualLight::spot({0, 2, 0}, {0, -1, 0}, Rgb(8.f), 0.2f, 0.3f)});
  EXPECT_NEAR(centre_radiance(scene, {0, 1, 0.001}, {0, 0, 0}, WhittedIntegrator()).g,
              rho_over_pi * 8 / 4, 1e-4);
  EXPECT_EQ(centre_radiance(scene, {1.5, 1, 0.001}, {1.5, 0, 0}, WhittedIntegrator()).g, 0.f);
}

TEST(PunctualLights, SpotFalloffRampsBetweenTheCones) {
  PunctualLight spot = PunctualLight::spot({0, 0, 0}, {0, 0, -1}, Rgb(1.f), 0.1f, 0.5f);
  EXPECT_FLOAT_EQ(spot.spot_falloff({0, 0, -1}), 1.f);
  EXPECT_EQ(spot.spot_falloff(normalize(Vector3f(1, 0, -1))), 0.f);  // 45° > 0.5 rad
  float mid = spot.spot_falloff({std::sin(0.3f), 0, -std::cos(0.3f)});
  EXPECT_GT(mid, 0.f);
  EXPECT_LT(mid, 1.f);
}

}  // namespace
}  // namespace obscura

// KHR_materials_transmission and _volume rendered by the path tracer, against closed forms:
// a slab of clear glass in front of a uniform light, Beer–Lambert absorption inside it, and
// the white furnace (a white transmissive sphere vanishes into a uniform white environment).
#include <gtest/gtest.h>

#include <cmath>

#include "obscura/film/film.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

constexpr float kF0 = 0.04f;  // ((1.5 − 1)/(1.5 + 1))²

Rgb film_mean(const Film& film) {
  Rgb sum;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) sum += film.pixel({x, y});
  return sum / float(film.width() * film.height());
}

Material glass(float thickness, Rgb attenuation_color = Rgb(1.f),
               float attenuation_distance = INFINITY) {
  MetallicRoughnessMaterial m;
  m.base_color = Rgb(1.f);
  m.metallic = 0;
  m.roughness = 0;
  m.transmission = 1;
  m.thickness = thickness;
  m.attenuation_color = attenuation_color;
  m.attenuation_distance = attenuation_distance;
  Material material;
  material.name = "glass";
  material.model = m;
  return material;
}

// The camera on +Z looks down −Z through a glass slab (faces at z = 0 and z = −d, 4 m wide) at a
// light of radiance 1 filling the view behind it; nothing else is there, so all it sees is the
// light the slab lets through (reflections show the black void).
Rgb seen_through_slab(const Material& material, float d, bool both_faces = true) {
  Scene scene;
  scene.materials = {material, diffuse_material("light", Rgb(0.f), Rgb(1.f))};
  std::vector<Mesh> meshes;
  meshes.push_back(testing::make_quad("front", 0, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}));
  if (both_faces)
    meshes.push_back(
        testing::make_quad("back", 0, {-2, -2, -d}, {-2, 2, -d}, {2, 2, -d}, {2, -2, -d}));
  meshes.push_back(
      testing::make_quad("light", 1, {-50, -50, -3}, {50, -50, -3}, {50, 50, -3}, {-50, 50, -3}));
  scene.add_meshes(meshes);
  scene.camera = testing::make_camera({0, 0, 2}, {0, 0, 0}, 16, 6);  // within 3° of normal
  TraceScene trace(scene, testing::embree_device());
  Film film(16, 16);
  render(trace, scene.camera, PathTracer(), {.samples_per_pixel = 256, .seed = 3}, film);
  return film_mean(film);
}

TEST(Transmission, ClearGlassSlabTransmitsTheAiryFraction) {
  // Two interfaces reflecting R = F0 each, light bouncing between them:
  // T = (1 − R)² Σ R^2k = (1 − R)² / (1 − R²). Each sample is 0 or 1 (σ ≈ 0.27); 65536 of them
  // put the mean within 0.002 (1σ): the tolerance is 0.006.
  const float expected = (1 - kF0) * (1 - kF0) / (1 - kF0 * kF0);
  Rgb volume = seen_through_slab(glass(0.1f), 0.1f);
  EXPECT_NEAR(volume.g, expected, 0.006f);
  // A thin-walled material (no volume) on the same two faces transmits the same at normal
  // incidence; one thin wall alone passes 1 − R.
  EXPECT_NEAR(seen_through_slab(glass(0), 0.1f).g, expected, 0.006f);
  EXPECT_NEAR(seen_through_slab(glass(0), 0.1f, false).g, 1 - kF0, 0.006f);
}

TEST(Transmission, BeerLambertAbsorptionInsideAVolume) {
  // A slab of thickness d, attenuation colour c at distance D: each crossing keeps τ = c^(d/D),
  // so T = (1 − R)² τ / (1 − R² τ²) ≈ c^(d/D) (1 − R)².
  const float d = 0.5f, distance = 0.25f;
  const Rgb c(0.8f, 0.5f, 0.2f);
  Rgb seen = seen_through_slab(glass(d, c, distance), d);
  for (int k = 0; k < 3; ++k) {
    float tau = std::pow(c[k], d / distance);
    float expected = (1 - kF0) * (1 - kF0) * tau / (1 - kF0 * kF0 * tau * tau);
    EXPECT_NEAR(seen[k], expected, 0.006f + 0.02f * expected) << k;
  }
  // A thin wall has no inside: nothing is absorbed.
  Material thin = glass(0, c, distance);
  EXPECT_NEAR(seen_through_slab(thin, d).b, (1 - kF0) * (1 - kF0) / (1 - kF0 * kF0), 0.006f);
}

TEST(Transmission, WhiteSphereVanishesInAWhiteFurnace) {
  // Nothing absorbs, so every path leaves with radiance 1 however it scattered. Smooth glass,
  // thin or refracting, and a half-transmissive white dielectric are exact: 16² pixels × 64
  // samples put the image mean within 0.01 (several standard errors). Rough glass is
  // single-scattering GGX without multiple-scattering compensation: measured 0.955 at
  // roughness 0.3 (α = 0.09), so it may lose up to 6 % but never gain.
  struct Case {
    float transmission, roughness, thickness, lowest;
  };
  for (Case k : {Case{1, 0, 1, 0.99f}, Case{1, 0, 0, 0.99f}, Case{0.5f, 0, 1, 0.99f},
                 Case{1, 0.3f, 1, 0.94f}}) {
    SCOPED_TRACE(::testing::Message() << "transmission " << k.transmission << " roughness "
                                      << k.roughness << " thickness " << k.thickness);
    Material m = glass(k.thickness);
    auto& mr = std::get<MetallicRoughnessMaterial>(m.model);
    mr.transmission = k.transmission;
    mr.roughness = k.roughness;
    Scene scene;
    scene.materials = {m};
    scene.add_meshes({testing::make_sphere({0, 0, 0}, 1, 0)});
    scene.camera = testing::make_camera({0, 0, 3}, {0, 0, 0}, 16, 40);  // the sphere fills it
    TraceScene trace(scene, testing::embree_device());
    trace.set_environment(EnvironmentLight(Rgb(1.f)));
    Film film(16, 16);
    render(trace, scene.camera, PathTracer(), {.samples_per_pixel = 64, .seed = 5}, film);
    EXPECT_GE(film_mean(film).g, k.lowest);
    EXPECT_LE(film_mean(film).g, 1.01f);
  }
}

}  // namespace
}  // namespace obscura

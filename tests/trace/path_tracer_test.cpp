#include "obscura/trace/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "obscura/scene/builtin_scenes.h"
#include "obscura/trace/render.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

std::shared_ptr<EmbreeDevice> device() {
  return testing::embree_device();
}

// A sphere of one material inside a uniform environment of radiance 1 (the "white furnace").
struct Furnace {
  Scene scene;
  Camera camera = testing::make_camera({0, 0, 4}, {0, 0, 0}, 16, 20);
  Furnace() {
    scene.name = "furnace";
    scene.materials = {diffuse_material("sphere", Rgb(1.f))};
    scene.add_meshes({testing::make_sphere({0, 0, 0}, 1, 0, 24, 48)});
    scene.camera = camera;
  }
};

struct PixelEstimate {
  double mean[3] = {}, standard_error[3] = {};
};

// Per pixel: the mean of `spp` radiance samples and its standard error.
std::vector<PixelEstimate> estimate_pixels(const TraceScene& scene, const Camera& camera,
                                           const Integrator& integrator, int spp) {
  std::vector<PixelEstimate> pixels;
  RayCounts counts;
  for (int y = 0; y < camera.film.height_px; ++y)
    for (int x = 0; x < camera.film.width_px; ++x) {
      double sum[3] = {}, sum2[3] = {};
      for (int s = 0; s < spp; ++s) {
        Sampler sampler(SamplerType::kIndependent, 1, {x, y}, uint32_t(s));
        Point2f u = sampler.next_2d();
        sampler.next_2d(), sampler.next_1d();  // the lens and time dimensions, unused
        std::optional<CameraRay> ray = camera.generate_ray({x + u.x, y + u.y});
        Rgb L = integrator.radiance(scene, ray->to_ray(), sampler, counts);
        for (int c = 0; c < 3; ++c) sum[c] += L[c], sum2[c] += double(L[c]) * L[c];
      }
      PixelEstimate p;
      for (int c = 0; c < 3; ++c) {
        p.mean[c] = sum[c] / spp;
        double variance = std::max(0.0, sum2[c] / spp - p.mean[c] * p.mean[c]);
        p.standard_error[c] = std::sqrt(variance / (spp - 1));
      }
      pixels.push_back(p);
    }
  return pixels;
}

TEST(PathTracer, WhiteFurnaceDiffuseSphereVanishes) {
  // An albedo-1 Lambertian sphere in a uniform environment of radiance 1 reflects exactly what
  // it receives: every pixel, sphere or not, is 1 (within 5 standard errors of its samples).
  Furnace furnace;
  TraceScene scene(furnace.scene, device());
  scene.set_environment(EnvironmentLight(Rgb(1.f)));
  for (auto strategy : {PathTracerSettings::Strategy::kMis, PathTracerSettings::Strategy::kBsdfOnly,
                        PathTracerSettings::Strategy::kLightOnly}) {
    PathTracer tracer({.strategy = strategy});
    for (const PixelEstimate& p : estimate_pixels(scene, furnace.camera, tracer, 64))
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(p.mean[c], 1.0, 5 * p.standard_error[c] + 1e-5) << int(strategy);
  }
}

TEST(PathTracer, AConstantEnvironmentIsLeftToBsdfSampling) {
  // A convex Lambertian of albedo ρ under a uniform environment L reflects ρL. Cosine sampling
  // draws directions in proportion to the integrand, so each path's single bounce carries exactly
  // ρL: with the environment left out of light sampling the estimate has (almost) no variance —
  // paths lost where the smooth normal and the facets disagree aside. Light-only paths, sampling
  // the sphere of directions uniformly, keep their full variance; both agree on the mean.
  Furnace furnace;
  TraceScene scene(furnace.scene, device());
  scene.set_environment(EnvironmentLight(Rgb(1.f)));
  scene.set_material(0, TraceMaterial(LambertianBsdf{Rgb(0.5f)}));
  double variance[2] = {}, mean[2] = {};
  int index = 0;
  for (auto strategy :
       {PathTracerSettings::Strategy::kMis, PathTracerSettings::Strategy::kLightOnly}) {
    std::vector<PixelEstimate> pixels =
        estimate_pixels(scene, furnace.camera, PathTracer({.strategy = strategy}), 64);
    for (const PixelEstimate& p : pixels) {
      variance[index] += p.standard_error[1] * p.standard_error[1];
      mean[index] += p.mean[1] / double(pixels.size());
    }
    ++index;
  }
  EXPECT_LT(variance[0], 0.01 * variance[1]);
  EXPECT_NEAR(mean[0], mean[1], 5 * std::sqrt(variance[1]) / 320);
}

TEST(PathTracer, FurnaceEnergyOfEveryBsdf) {
  // Lossless BSDFs (white Lambertian, smooth glass, white metals and white glTF materials, whose
  // microfacet lobes carry Kulla–Conty's multiple scattering) give exactly 1; the others lose
  // energy (rough glass's microfacet masking, Phong's absorption) and must stay ≤ 1 — never
  // above.
  struct Case {
    const char* name;
    AnyBsdf bsdf;
    bool lossless;
  };
  const Case cases[] = {
      {"lambertian", LambertianBsdf{Rgb(1.f)}, true},
      {"smooth glass", DielectricBsdf(1.5f, 0), true},
      {"rough glass", DielectricBsdf(1.5f, 0.3f), false},
      {"rough white metal", ConductorBsdf(Rgb(1.f), Rgb(1e4f), 0.4f), true},
      {"mirror", ConductorBsdf(Rgb(1.f), Rgb(1e4f), 0), true},
      {"phong", PhongBsdf(Rgb(0.5f), Rgb(0.5f), 30, false), false},
      {"blinn-phong", PhongBsdf(Rgb(0.5f), Rgb(0.5f), 30, true), false},
      {"metallic-roughness",
       MetallicRoughnessBsdf({.base_color = Rgb(1.f), .metallic = 0.5f, .roughness = 0.4f}), true},
  };
  Furnace furnace;
  for (const Case& c : cases) {
    TraceScene scene(furnace.scene, device());
    scene.set_environment(EnvironmentLight(Rgb(1.f)));
    scene.set_material(0, TraceMaterial(c.bsdf));
    // Judged on the image mean and the spread of the pixel means, not pixel by pixel: with the
    // constant environment left to BSDF sampling, a glossy pixel's samples are ~1.2 or, for the
    // ~10 % of visible normals that reflect below the horizon, 0 — a pixel that drew no 0 in
    // its 32 samples shows a mean of 1.2 with a tiny sample variance, though unbiased.
    std::vector<PixelEstimate> pixels = estimate_pixels(scene, furnace.camera, PathTracer(), 32);
    double sum = 0, sum2 = 0;
    for (const PixelEstimate& p : pixels) sum += p.mean[1], sum2 += p.mean[1] * p.mean[1];
    double n = double(pixels.size()), mean = sum / n;
    double standard_error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
    // 2e-3: the accuracy of the tabulated GGX albedos (shading/ggx_energy.h).
    double bound = 4 * standard_error + 2e-3;
    if (c.lossless) {
      EXPECT_NEAR(mean, 1.0, bound) << c.name;
    }
    EXPECT_LE(mean, 1 + bound) << c.name << ": reflects more than it receives";
    EXPECT_GT(mean, 0.75) << c.name;  // and loses only a little
  }
}

TEST(PathTracer, KhronosFurnaceTestOfTheMetalRoughGrid) {
  // The Khronos furnace test: a grid of white glTF materials sweeping metallic × roughness (as
  // MetalRoughSpheres) in a uniform white environment disappears into the background. Each
  // material's image mean (sphere and background) is 1 within 4 standard errors of that mean
  // plus the tables' 2e-3. Without multiple scattering, a white metal of roughness 1 reflects
  // only E(μ) of what arrives (1 − ln 2 ≈ 0.31 at normal incidence).
  Furnace furnace;
  for (float metallic : {0.f, 0.5f, 1.f})
    for (float roughness : {0.05f, 0.3f, 0.6f, 1.f}) {
      TraceScene scene(furnace.scene, device());
      scene.set_environment(EnvironmentLight(Rgb(1.f)));
      scene.set_material(
          0, TraceMaterial(MetallicRoughnessBsdf(
                 {.base_color = Rgb(1.f), .metallic = metallic, .roughness = roughness})));
      double sum = 0, sum2 = 0;
      std::vector<PixelEstimate> pixels = estimate_pixels(scene, furnace.camera, PathTracer(), 32);
      for (const PixelEstimate& p : pixels) sum += p.mean[1], sum2 += p.mean[1] * p.mean[1];
      double n = double(pixels.size()), mean = sum / n;
      double standard_error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
      EXPECT_NEAR(mean, 1, 4 * standard_error + 2e-3)
          << "metallic " << metallic << " roughness " << roughness;
    }
}

// The built-in Cornell box, small, for comparing estimators.
double image_mean(const Film& film, Bounds2i region) {
  double sum = 0;
  for (int y = region.min.y; y < region.max.y; ++y)
    for (int x = region.min.x; x < region.max.x; ++x) sum += luminance(film.pixel({x, y}));
  return sum / (region.width() * region.height());
}

TEST(PathTracer, LightSamplingBsdfSamplingAndMisConvergeToTheSameImage) {
  Scene cornell = make_builtin_scene("cornell-box");
  cornell.camera.film.width_px = cornell.camera.film.height_px = 24;
  TraceScene scene(cornell, device());
  using Strategy = PathTracerSettings::Strategy;
  std::vector<Film> films;
  for (Strategy strategy : {Strategy::kMis, Strategy::kLightOnly, Strategy::kBsdfOnly}) {
    films.emplace_back(24, 24);
    render(scene, cornell.camera, PathTracer({.max_depth = 8, .strategy = strategy}),
           {.samples_per_pixel = strategy == Strategy::kBsdfOnly ? 1024 : 256, .seed = 3},
           films.back());
  }
  // Whole image and its four quadrants agree within a few percent (the BSDF-only estimate of a
  // small light is the noisiest; its quadrant means carry about 1 % standard error here).
  std::vector<Bounds2i> regions = {{{0, 0}, {24, 24}},
                                   {{0, 0}, {12, 12}},
                                   {{12, 0}, {24, 12}},
                                   {{0, 12}, {12, 24}},
                                   {{12, 12}, {24, 24}}};
  for (const Bounds2i& r : regions) {
    double mis = image_mean(films[0], r);
    EXPECT_NEAR(image_mean(films[1], r) / mis, 1.0, 0.03) << "light only";
    EXPECT_NEAR(image_mean(films[2], r) / mis, 1.0, 0.05) << "BSDF only";
  }
}

}  // namespace
}  // namespace obscura

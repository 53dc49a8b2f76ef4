// Spectral light transport in the path tracer, against physics: the white furnace at every
// wavelength, the same image as RGB transport where nothing disperses, a blackbody emitter's
// published chromaticity, and Snell's law per wavelength through a dispersive glass.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "obscura/color/blackbody_spectrum.h"
#include "obscura/color/primaries.h"
#include "obscura/color/spectral.h"
#include "obscura/film/film.h"
#include "obscura/film/image_metrics.h"
#include "obscura/scene/builtin_scenes.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "obscura/trace/whitted.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

// CIE D65 at unit luminance, summed here from the tables.
double white_illuminant(double nm) {
  static const double y = [] {
    double sum = 0;
    for (int l = 360; l <= 830; ++l) sum += d65_spd(l) * cmf_xyz(l)[1];
    return sum;
  }();
  return d65_spd(nm) / y;
}

Image render_image(const Scene& scene, bool spectral, int spp, uint64_t seed, int tile_size = 16,
                   int max_depth = 65) {
  TraceScene trace(scene, testing::embree_device());
  Film film(scene.camera.film.width_px, scene.camera.film.height_px);
  render(trace, scene.camera, PathTracer({.max_depth = max_depth}),
         {.samples_per_pixel = spp, .seed = seed, .tile_size = tile_size, .spectral = spectral},
         film);
  return film.to_image();
}

Vec3d image_mean(const Image& image) {
  Vec3d sum{};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) sum[c] += image.at(x, y, c);
  for (double& v : sum) v /= double(image.width) * image.height;
  return sum;
}

TEST(SpectralRender, WhiteFurnaceHoldsAtEveryWavelength) {
  // A white (albedo 1) Lambertian sphere in a uniform white environment reflects exactly what
  // it receives, at each wavelength: the radiance at wavelength i over the white illuminant's
  // value there is the same for the three wavelengths of every path, and 1 on average.
  Scene scene;
  scene.materials = {diffuse_material("sphere", Rgb(1.f))};
  scene.add_meshes({testing::make_sphere({0, 0, 0}, 1, 0, 24, 48)});
  scene.camera = testing::make_camera({0, 0, 4}, {0, 0, 0}, 12, 20);
  TraceScene trace(scene, testing::embree_device());
  trace.set_environment(EnvironmentLight(Rgb(1.f)));
  PathTracer tracer;
  RayCounts counts;
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x)
      for (int s = 0; s < 32; ++s) {
        Sampler sampler(SamplerType::kIndependent, 1, {x, y}, uint32_t(s));
        SampledWavelengths w = SampledWavelengths::sample(sampler.next_1d());
        std::optional<CameraRay> ray = scene.camera.generate_ray({x + 0.5, y + 0.5});
        Rgb L = tracer.spectral_radiance(trace, ray->to_ray(), w, sampler, counts);
        double ratio[3];
        for (int i = 0; i < 3; ++i) ratio[i] = L[i] / white_illuminant(w.nm(i));
        ASSERT_NEAR(ratio[1], ratio[0], 1e-4) << w.nm(0) << " " << w.nm(1);
        ASSERT_NEAR(ratio[2], ratio[0], 1e-4) << w.nm(0) << " " << w.nm(2);
        sum += ratio[0], sum2 += ratio[0] * ratio[0], ++n;
      }
  double mean = sum / n, standard_error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, 1.0, 5 * standard_error + 1e-5);
  // And the image: white, to within the wavelength sampling's noise.
  Film film(12, 12);
  render(trace, scene.camera, tracer, {.samples_per_pixel = 64, .seed = 2, .spectral = true}, film);
  Vec3d m = image_mean(film.to_image());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c], 1.0, 0.01) << c;
}

TEST(SpectralRender, AnRgbSceneRendersTheSameInBothModes) {
  // The Cornell box (RGB reflectances and light): the spectral image differs from the RGB one by
  // no more than two renders of one mode differ between seeds.
  Scene scene = make_cornell_box();
  scene.camera.film.width_px = scene.camera.film.height_px = 24;
  const int spp = 64;
  Image rgb_a = render_image(scene, false, spp, 1), rgb_b = render_image(scene, false, spp, 2);
  Image spectral_a = render_image(scene, true, spp, 1);
  Image spectral_b = render_image(scene, true, spp, 2);
  double noise_rgb = rmse(rgb_a, rgb_b, 3), noise_spectral = rmse(spectral_a, spectral_b, 3);
  // Independent renders of one expected image differ by √(σ₁² + σ₂²).
  double expected = std::sqrt((noise_rgb * noise_rgb + noise_spectral * noise_spectral) / 2);
  double between = rmse(rgb_a, spectral_b, 3);
  EXPECT_LT(between, 1.2 * expected)
      << "rgb noise " << noise_rgb << ", spectral " << noise_spectral;
}

TEST(SpectralRender, DirectLightFromAWhiteLampIsTheSameInBothModes) {
  // Light that meets one coloured surface between a white lamp and the eye has, spectrally, the
  // colour of reflectance × white: the lifted reflectance's colour under D65, which is its RGB.
  // (Over more bounces, or under a coloured lamp, spectral products of colours differ from RGB
  // products — by 2–5 % in the Cornell box's means — as they do in the world.) So the direct
  // light image's means (far less noisy than its pixels) agree within 1 %.
  Scene scene = make_cornell_box();
  scene.camera.film.width_px = scene.camera.film.height_px = 24;
  for (Material& m : scene.materials)
    if (!m.emission.is_black()) m.emission = Rgb(luminance(m.emission));
  Vec3d rgb = image_mean(render_image(scene, false, 256, 1, 16, 2));
  Vec3d spectral = image_mean(render_image(scene, true, 256, 1, 16, 2));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(spectral[c], rgb[c], 0.01 * rgb[c]) << c;
}

TEST(SpectralRender, ABlackbodyEmitterHasItsIlluminantsChromaticity) {
  // CIE illuminant A is Planck's law at 2856 K with the old c₂ = 1.435e-2 m·K; with today's
  // c₂ = hc/k = 1.438777e-2 m·K the same spectrum is at 2856 × 1.438777 / 1.435 K. Published
  // chromaticity (CIE 15): x = 0.44757, y = 0.40745. Seen directly, a quad emitting it fills
  // the view; strength 3 sets its luminance.
  const float kelvin = float(2856 * 1.438777 / 1.435);
  Material light;
  light.name = "lamp";
  light.model = EmissiveMaterial{};
  light.emission_kelvin = kelvin;
  light.emission = BlackbodySpectrum(kelvin).working_rgb() * 3.f;
  Scene scene;
  scene.materials = {light};
  scene.add_meshes(
      {testing::make_quad("lamp", 0, {-5, -5, -1}, {5, -5, -1}, {5, 5, -1}, {-5, 5, -1})});
  scene.camera = testing::make_camera({0, 0, 1}, {0, 0, 0}, 8, 30);
  const Matrix3d xyz_from_rec709 = xyz_from_rgb(primaries::kRec709);
  for (bool spectral : {true, false}) {
    Vec3d rgb = image_mean(render_image(scene, spectral, 64, 5));
    Chromaticity xy = chromaticity_of(xyz_from_rec709 * rgb);
    EXPECT_NEAR(xy.x, 0.44757, 1e-3) << spectral;
    EXPECT_NEAR(xy.y, 0.40745, 1e-3) << spectral;
    EXPECT_NEAR((xyz_from_rec709 * rgb)[1], 3.0, 0.01) << spectral;
  }
}

// n(λ) of a glass from n_d and V_d: the two Cauchy coefficients solved here from n(587.56) = n_d
// and n(486.13) − n(656.27) = (n_d − 1)/V_d as a 2 × 2 linear system in (A, B).
double cauchy_index(double n_d, double abbe, double nm) {
  const double d = 1 / (587.56 * 587.56), f = 1 / (486.13 * 486.13), c = 1 / (656.27 * 656.27);
  // [1 d; 0 f − c] (A, B) = (n_d, (n_d − 1)/V)
  double b = (n_d - 1) / abbe / (f - c);
  double a = n_d - d * b;
  return a + b / (nm * nm);
}

TEST(SpectralRender, DispersiveGlassRefractsEachWavelengthBySnellsLaw) {
  // A dense flint (n_d 1.7847, V_d 25.76, SF11-like): light at 50° from the normal refracts to
  // asin(sin 50° / n(λ)) for the path's hero wavelength, in RGB mode by n_d alone; blue bends
  // more than red.
  DielectricMaterial flint{.ior = 1.7847f, .roughness = 0, .abbe_number = 25.76f};
  Material material;
  material.model = flint;
  TraceMaterial traced(material, nullptr);
  EXPECT_TRUE(traced.disperses());
  SurfaceHit hit{};
  const float theta = 50 * std::numbers::pi_v<float> / 180;
  Vector3f wo(std::sin(theta), 0, std::cos(theta));
  auto refracted_sine = [&](const SampledWavelengths* w) {
    AnyBsdf bsdf = traced.bsdf_at(hit, w);
    // Choose refraction: a lobe number past the Fresnel reflectance (< 0.2 here).
    std::optional<BsdfSample> s = bsdf.sample(wo, 0.99f, {0.5f, 0.5f});
    EXPECT_TRUE(s && s->is_transmission);
    return std::sqrt(s->wi.x * s->wi.x + s->wi.y * s->wi.y);
  };
  double previous_sine = 0;
  for (float u : {0.05f, 0.3f, 0.55f, 0.8f}) {  // heroes from violet to red
    SampledWavelengths w = SampledWavelengths::sample(u);
    double n = cauchy_index(1.7847, 25.76, w.hero_nm());
    double sine = refracted_sine(&w);
    EXPECT_NEAR(sine, std::sin(theta) / n, 2e-5) << w.hero_nm();
    EXPECT_GT(sine, previous_sine) << "longer waves bend less";
    previous_sine = sine;
  }
  EXPECT_NEAR(refracted_sine(nullptr), std::sin(theta) / 1.7847, 2e-5);
  // The F and C lines' indices differ by (n_d − 1)/V_d, as the Abbe number says.
  EXPECT_NEAR(flint.ior_at(486.13f) - flint.ior_at(656.27f), 0.7847 / 25.76, 1e-5);
  EXPECT_NEAR(flint.ior_at(587.56f), 1.7847, 1e-6);
}

TEST(SpectralRender, APrismSplitsWhiteLightOnlyInSpectralMode) {
  // A camera looks level through a 60° glass prism (n_d 1.5, V_d 20: strongly dispersive) at a
  // lit strip on the floor that only the prism's deviation (about 40°, downwards) brings into
  // view. In spectral mode blue deviates more than red (n_F − n_C = 0.025: about 2°, some three
  // pixels here), so the strip's red and blue images part; RGB mode, one index for all light,
  // keeps them together.
  Scene scene;
  Material glass;
  glass.name = "glass";
  glass.model = DielectricMaterial{.ior = 1.5f, .abbe_number = 20};
  scene.materials = {glass, diffuse_material("strip", Rgb(0.f), Rgb(20.f))};
  // The prism: a triangular bar along z, apex up, faces pointing outwards.
  const float h = 0.866f;
  Point3f a0{-0.5f, 0, 1}, b0{0.5f, 0, 1}, c0{0, h, 1}, a1{-0.5f, 0, -1}, b1{0.5f, 0, -1},
      c1{0, h, -1};
  Mesh caps;
  caps.name = "caps";
  caps.positions = {a0, b0, c0, a1, c1, b1};
  caps.indices = {0, 1, 2, 3, 4, 5};
  scene.add_meshes(
      {testing::make_quad("base", 0, a0, a1, b1, b0), testing::make_quad("left", 0, a0, c0, c1, a1),
       testing::make_quad("right", 0, b0, b1, c1, c0), caps,
       testing::make_quad("strip", 1, {3, -3, -3}, {3, -3, 3}, {5, -3, 3}, {5, -3, -3})});
  scene.camera = testing::make_camera({-4, 0.43, 0}, {0, 0.43, 0}, 48, 30);
  auto centroids = [&](bool spectral) {
    Image image = render_image(scene, spectral, 64, 7);
    double sum[2] = {}, weighted[2] = {};
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c : {0, 2}) {
          double v = std::max(0.f, image.at(x, y, c));
          sum[c / 2] += v, weighted[c / 2] += v * y;
        }
    EXPECT_GT(sum[0], 0);
    EXPECT_GT(sum[1], 0);
    return std::pair{weighted[0] / sum[0], weighted[1] / sum[1]};
  };
  auto [red_rgb, blue_rgb] = centroids(false);
  auto [red_spectral, blue_spectral] = centroids(true);
  EXPECT_NEAR(red_rgb, blue_rgb, 0.01);
  EXPECT_GT(std::abs(red_spectral - blue_spectral), 1.0)
      << "red " << red_spectral << ", blue " << blue_spectral;
}

TEST(SpectralRender, IsDeterministicAndOnlyThePathTracerHasIt) {
  Scene scene = make_cornell_box();
  scene.camera.film.width_px = scene.camera.film.height_px = 16;
  Image a = render_image(scene, true, 4, 9, 4), b = render_image(scene, true, 4, 9, 16);
  EXPECT_EQ(rmse(a, b, 3), 0.0);
  TraceScene trace(scene, testing::embree_device());
  Film film(16, 16);
  EXPECT_THROW(render(trace, scene.camera, WhittedIntegrator(),
                      {.samples_per_pixel = 1, .spectral = true}, film),
               Error);
}

}  // namespace
}  // namespace obscura

#include "obscura/trace/area_lights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "obscura/math/rng.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

// A square emitter of radiance 1, side 2·a, centred above the origin at height h and facing
// down (−Y), split into two triangles.
AreaLights square_light(float a, float h, AreaLightSampling sampling) {
  std::vector<Material> materials = {diffuse_material("lamp", Rgb(0.f), Rgb(1.f))};
  std::vector<Mesh> meshes = {
      testing::make_quad("lamp", 0, {-a, h, -a}, {a, h, -a}, {a, h, a}, {-a, h, a})};
  return AreaLights(meshes, materials, sampling);
}

struct Estimate {
  double mean = 0, variance = 0;
};

// Irradiance at the origin on a surface facing +Y: E = ∫ L cos θ dω, by n light samples.
Estimate irradiance(const AreaLights& lights, int n) {
  Pcg32 rng(11);
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    float u0 = rng.next_float(), u1 = rng.next_float(), u2 = rng.next_float();
    std::optional<AreaLightSample> s = lights.sample({0, 0, 0}, u0, {u1, u2});
    double e = s ? s->radiance.g * std::max(0.f, s->wi.y) / s->pdf : 0;
    sum += e, sum2 += e * e;
  }
  double mean = sum / n;
  return {mean, (sum2 / n - mean * mean)};
}

// A differential area facing a centred square of side 2a at height h receives, from radiance L,
// E = π L F with the form factor F = 4 × the corner rectangle's
// (1/2π)·[a/√(a²+h²)·atan(a/√(a²+h²)) · 2] (Howell's catalogue, configuration A-3 for a = b):
// E = 4 L · a/√(a²+h²) · atan(a/√(a²+h²)).
double analytic_irradiance(double a, double h) {
  double s = a / std::sqrt(a * a + h * h);
  return 4 * s * std::atan(s);
}

TEST(AreaLights, IrradianceFromASquareMatchesItsFormFactor) {
  for (float h : {0.2f, 1.f, 5.f}) {
    for (auto sampling : {AreaLightSampling::kSolidAngle, AreaLightSampling::kArea}) {
      AreaLights lights = square_light(1, h, sampling);
      const int n = 40000;
      Estimate e = irradiance(lights, n);
      double standard_error = std::sqrt(e.variance / n);
      EXPECT_NEAR(e.mean, analytic_irradiance(1, h), 5 * standard_error + 1e-6)
          << "h " << h << " sampling " << int(sampling);
    }
  }
}

TEST(AreaLights, SolidAngleSamplingHasLowerVarianceUpClose) {
  // At h = 0.2 under a 2 × 2 square, area sampling's d²/cos weights vary by orders of magnitude
  // across the light; uniform solid-angle sampling leaves only the receiver's cos θ to vary.
  double area = irradiance(square_light(1, 0.2f, AreaLightSampling::kArea), 20000).variance;
  double solid = irradiance(square_light(1, 0.2f, AreaLightSampling::kSolidAngle), 20000).variance;
  EXPECT_LT(solid, 0.25 * area) << "solid-angle variance " << solid << ", area " << area;
}

TEST(AreaLights, PdfIsANormalizedDensityAndMatchesSample) {
  // Two emitters: a large square close by (spherical sampling) and a tiny far triangle (area
  // sampling). For each sampling mode, ∫ pdf dω over all lights = Σ ∫ pdf cos/d² dA = 1
  // (midpoint rule on a fine grid), and pdf() at a sampled point equals the sample's pdf.
  std::vector<Material> materials = {diffuse_material("lamp", Rgb(1.f), Rgb(2.f))};
  std::vector<Mesh> meshes = {
      testing::make_quad("near", 0, {-1, 0.5f, -1}, {1, 0.5f, -1}, {1, 0.5f, 1}, {-1, 0.5f, 1}),
      testing::make_quad("far", 0, {20, 30, 0}, {20.01f, 30, 0}, {20.01f, 30, 0.01f},
                         {20, 30, 0.01f})};
  Point3f p{0.3f, 0, 0.1f};
  for (auto sampling : {AreaLightSampling::kSolidAngle, AreaLightSampling::kArea}) {
    AreaLights lights(meshes, materials, sampling);
    double integral = 0;
    const int m = 400;
    for (uint32_t mesh = 0; mesh < 2; ++mesh)
      for (uint32_t tri = 0; tri < 2; ++tri) {
        const Mesh& q = meshes[mesh];
        Point3f p0 = q.positions[q.indices[3 * tri]], p1 = q.positions[q.indices[3 * tri + 1]],
                p2 = q.positions[q.indices[3 * tri + 2]];
        Vector3f n = cross(p1 - p0, p2 - p0);
        double area = 0.5 * length(n);
        n = normalize(n);
        for (int i = 0; i < m; ++i)
          for (int j = 0; j < m - i; ++j) {
            float b1 = (i + 1.f / 3) / m, b2 = (j + 1.f / 3) / m;  // lower micro-triangles…
            for (int upper = 0; upper < (i + j < m - 1 ? 2 : 1); ++upper) {
              if (upper) b1 = (i + 2.f / 3) / m, b2 = (j + 2.f / 3) / m;  // …and upper ones
              Point3f x = p0 + (p1 - p0) * b1 + (p2 - p0) * b2;
              Vector3f d = x - p;
              double d2 = length_squared(d), cos_light = -dot(n, d) / std::sqrt(d2);
              integral += lights.pdf(p, mesh, tri, x) * cos_light / d2 * area / (m * m);
            }
          }
      }
    EXPECT_NEAR(integral, 1.0, 2e-3) << int(sampling);

    Pcg32 rng(3);
    for (int k = 0; k < 200; ++k) {
      float u0 = rng.next_float();
      std::optional<AreaLightSample> s = lights.sample(p, u0, {rng.next_float(), rng.next_float()});
      ASSERT_TRUE(s);
      uint32_t mesh = s->position.y > 10 ? 1 : 0;
      // Which of the quad's two triangles: the diagonal p0–p2 splits it.
      const Mesh& q = meshes[mesh];
      Vector3f diag = q.positions[2] - q.positions[0], off = s->position - q.positions[0];
      uint32_t tri = cross(diag, off).y > 0 ? 0 : 1;
      EXPECT_NEAR(lights.pdf(p, mesh, tri, s->position), s->pdf, 2e-3f * s->pdf)
          << "sample " << k << " mode " << int(sampling);
    }
  }
}

TEST(AreaLights, NothingFromBehind) {
  AreaLights lights = square_light(1, 1, AreaLightSampling::kSolidAngle);
  EXPECT_FALSE(lights.sample({0, 2, 0}, 0.3f, {0.5f, 0.5f}));
  EXPECT_EQ(lights.pdf({0, 2, 0}, 0, 0, {0.1f, 1, 0.1f}), 0.f);
}

}  // namespace
}  // namespace obscura

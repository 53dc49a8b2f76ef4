// Shading: a finely tessellated sphere under one directional light with per-pixel Phong shading
// against the Phong reflection model evaluated analytically at the point where each pixel
// centre's ray meets the true sphere (ray casting and the formula written out here, in double,
// with glm's camera matrices), in both conventions: energy-conserving (the BRDF
// k_d/π + k_s·(n+2)/2π·(R·V)ⁿ times the irradiance E·cos θ, as the tracer's PhongBsdf) and
// classic (E·(k_d·cos θ + k_s·(R·V)ⁿ)).
#include "obscura/raster/phong.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "obscura/raster/pipeline.h"
#include "obscura/raster/shaders.h"

namespace obscura::raster {
namespace {

constexpr int kSize = 96;

Matrix4 to_matrix4(const glm::dmat4& m) {  // glm is column-major: m[column][row]
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[i][j] = m[j][i];
  return r;
}

class PhongSphere : public ::testing::TestWithParam<PhongConvention> {};

TEST_P(PhongSphere, MatchesAnalyticReflection) {
  const bool classic = GetParam() == PhongConvention::kClassic;
  const int rings = 384, segments = 768;
  std::vector<MeshVertex> vertices;
  std::vector<uint32_t> indices;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {
      double phi = M_PI * r / rings, theta = 2 * M_PI * s / segments;
      Vector3f n(float(std::sin(phi) * std::cos(theta)), float(std::cos(phi)),
                 float(std::sin(phi) * std::sin(theta)));
      vertices.push_back({Point3f(n.x, n.y, n.z), n, {}, Rgb(1.f), 1.f, {}, {}});
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      uint32_t a = r * (segments + 1) + s, b = a + 1, c = a + segments + 1, d = c + 1;
      // Counter-clockwise seen from outside, so back-face culling keeps the visible half.
      for (uint32_t i : {a, b, c, b, d, c}) indices.push_back(i);
    }

  const glm::dvec3 eye(0.4, 0.5, 3.2);
  glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0), glm::dvec3(0, 1, 0));
  glm::dmat4 proj = glm::perspective(glm::radians(45.0), 1.0, 0.5, 10.0);
  const glm::dvec3 to_light = glm::normalize(glm::dvec3(0.5, 0.8, 0.6));
  const glm::dvec3 kd(0.6, 0.4, 0.3), ks(0.35, 0.35, 0.35), ka(0.05, 0.1, 0.15);
  const double shininess = 12, ambient_light = 0.5;
  const glm::dvec3 light(0.9, 1.0, 0.8);

  LightSet lights;
  lights.ambient = Rgb(float(ambient_light));
  lights.directional.push_back({Vector3f(float(to_light.x), float(to_light.y), float(to_light.z)),
                                Rgb(float(light.x), float(light.y), float(light.z))});
  PhongProgram<SpecularModel::kPhong> program;
  program.scene = {Matrix4f(to_matrix4(proj * view)),
                   Point3f(float(eye.x), float(eye.y), float(eye.z)), &lights};
  program.material = {Rgb(float(ka.x), float(ka.y), float(ka.z)),
                      Rgb(float(kd.x), float(kd.y), float(kd.z)),
                      Rgb(float(ks.x), float(ks.y), float(ks.z)), float(shininess), GetParam()};
  RenderTarget target(kSize, kSize);
  target.clear();
  DrawState state;
  state.cull = CullMode::kBack;
  draw_with_depth_func<DepthFunc::kLess>(target, state, program, vertices, indices);

  glm::dmat4 world_from_clip = glm::inverse(proj * view);
  int checked = 0;
  double max_error = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      glm::dvec4 far =
          world_from_clip * glm::dvec4(2 * (x + 0.5) / kSize - 1, 1 - 2 * (y + 0.5) / kSize, 1, 1);
      glm::dvec3 d = glm::normalize(glm::dvec3(far) / far.w - eye);
      double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1, disc = b * b - c;
      // Skip the silhouette, where the tessellated outline differs from the true one.
      if (disc < 0.05) continue;
      glm::dvec3 p = eye + d * (-b - std::sqrt(disc));
      glm::dvec3 n = p, v = -d;
      double n_dot_l = glm::dot(n, to_light);
      glm::dvec3 expected = ka * ambient_light;
      if (n_dot_l > 0) {
        glm::dvec3 r = 2 * n_dot_l * n - to_light;
        double lobe = std::pow(std::max(glm::dot(r, v), 0.0), shininess);
        if (classic) {
          expected += light * (kd * n_dot_l + ks * lobe);
        } else {
          // k_d + k_s ≤ 1 in every channel here, so no energy scaling applies.
          expected += light * n_dot_l * (kd / M_PI + ks * ((shininess + 2) / (2 * M_PI)) * lobe);
        }
      }
      Rgb got = target.color_at(x, y);
      for (int k = 0; k < 3; ++k) max_error = std::max(max_error, std::abs(got[k] - expected[k]));
      ++checked;
    }
  EXPECT_GT(checked, 2000);
  EXPECT_LT(max_error, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Conventions, PhongSphere,
                         ::testing::Values(PhongConvention::kEnergyConserving,
                                           PhongConvention::kClassic),
                         [](const auto& info) {
                           return info.param == PhongConvention::kClassic ? "Classic"
                                                                          : "EnergyConserving";
                         });

// Energy conservation: where k_d + k_s exceeds 1, both are scaled by the largest sum.
TEST(Shading, EnergyConservingPhongNeverReflectsMoreThanArrives) {
  PhongMaterial m{Rgb(), Rgb(0.9f, 0.5f, 0.1f), Rgb(0.6f), 0};  // n = 0: a constant lobe
  LightSet lights;
  lights.directional.push_back({Vector3f(0, 1, 0), Rgb(1.f)});
  Rgb c = shade_phong<SpecularModel::kPhong>(m, lights, Point3f(), Vector3f(0, 1, 0),
                                             Vector3f(0, 1, 0));
  // f = (k_d/π + k_s/π)/1.5 (c(0) = 1/π), times E cos θ = 1.
  EXPECT_NEAR(c.r, (0.9 + 0.6) / 1.5 / M_PI, 1e-6);
  EXPECT_NEAR(c.b, (0.1 + 0.6) / 1.5 / M_PI, 1e-6);
}

TEST(Shading, SpecularPowerIsExactForIntegerExponents) {
  EXPECT_FLOAT_EQ(specular_power(0.5f, 3), 0.125f);
  EXPECT_FLOAT_EQ(specular_power(0.9f, 32), std::pow(0.9f, 32.f));
  EXPECT_FLOAT_EQ(specular_power(0.7f, 0), 1.f);
  EXPECT_NEAR(specular_power(0.7f, 2.5f), std::pow(0.7, 2.5), 1e-6);
}

TEST(Shading, BlinnPhongUsesTheHalfVector) {
  // Light and eye mirrored about the normal: H = N, so the lobe is 1 for any exponent.
  PhongMaterial m{Rgb(), Rgb(), Rgb(1.f), 64, PhongConvention::kClassic};
  LightSet lights;
  lights.directional.push_back({normalize(Vector3f(1, 1, 0)), Rgb(1.f)});
  Rgb c = shade_phong<SpecularModel::kBlinnPhong>(m, lights, Point3f(), Vector3f(0, 1, 0),
                                                  normalize(Vector3f(-1, 1, 0)));
  EXPECT_NEAR(c.r, 1.f, 1e-6);
}

TEST(Shading, PointAndSpotLightsFallOffWithDistanceAndCone) {
  PhongMaterial m{Rgb(), Rgb(1.f), Rgb(), 1, PhongConvention::kClassic};
  LightSet lights;
  lights.point.push_back({Point3f(0, 2, 0), Rgb(4.f)});
  Rgb c = shade_phong<SpecularModel::kPhong>(m, lights, Point3f(), Vector3f(0, 1, 0),
                                             Vector3f(0, 1, 0));
  EXPECT_NEAR(c.r, 1.f, 1e-6);  // 4 / 2², facing the light
  LightSet spot;
  spot.spot.push_back({Point3f(0, 1, 0), Vector3f(0, -1, 0), Rgb(1.f), 0.99f, 0.95f});
  EXPECT_NEAR(
      shade_phong<SpecularModel::kPhong>(m, spot, Point3f(), Vector3f(0, 1, 0), Vector3f(0, 1, 0))
          .r,
      1.f, 1e-6);
  EXPECT_EQ(shade_phong<SpecularModel::kPhong>(m, spot, Point3f(1, 0, 0), Vector3f(0, 1, 0),
                                               Vector3f(0, 1, 0))
                .r,
            0.f);  // 45° off axis: outside the cone
}

}  // namespace
}  // namespace obscura::raster

// Light units (docs/scene-format.md, "Light units"): a light given in lumens, in candela, in
// watts through 683 lm/W or in lux lights a grey card as hand computation says — E = I/d² under
// a point light, then L = ρE/π — and the photometric and radiometric descriptions of the same
// light render the same image.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "gltf_hostile.h"
#include "obscura/io/json_scene.h"
#include "obscura/render/render_frame.h"
#include "test_files.h"

namespace obscura {
namespace {

constexpr double kPi = std::numbers::pi;

// The luminance at the centre of a card (reflectance 0.5) 2 m below `light`, seen from 1 m
// above it; 49 × 49 pixels, so the centre pixel's centre looks straight down.
double card_luminance(const std::string& light) {
  std::string text = R"({"materials": {"card": {"type": "diffuse", "reflectance": 0.5}},
      "objects": [{"name": "card", "shape": "rectangle", "size": [100, 100], "material": "card"}],
      "lights": [)";
  text += light;
  text += R"(], "cameras": [{"name": "c", "type": "perspective", "position": [0, 1, 0],
      "target": [0, 0, 0], "up": [0, 0, -1], "focal_length_mm": 50}]})";
  Scene scene = load_json_scene_text(text, "units.json");
  scene.camera.film.width_px = scene.camera.film.height_px = 49;
  FrameSettings settings;
  settings.samples_per_pixel = 1;
  return render_frame(scene, scene.camera, settings, false).finished().at(24, 24, 1);
}

const char* kPoint = R"({"name": "bulb", "type": "point", "position": [0, 2, 0], )";
const char* kSun = R"({"name": "sun", "type": "directional", "direction": [0, -1, 0], )";

TEST(LightUnits, PointLightInCandelaLumensAndWatts) {
  // 100 cd at 2 m: E = 100 / 2² = 25 lux; L = 0.5 · 25 / π cd/m².
  const double hand = 0.5 * 25 / kPi;
  EXPECT_NEAR(card_luminance(std::string(kPoint) + R"("intensity": 100})") / hand, 1, 1e-5);
  EXPECT_NEAR(card_luminance(std::string(kPoint) + R"("intensity_cd": 100})") / hand, 1, 1e-5);
  // Lumens: I = Φ / 4π (KHR_lights_punctual's conversion).
  EXPECT_NEAR(
      card_luminance(std::string(kPoint) + R"("power_lm": )" + std::to_string(400 * kPi) + "}") /
          hand,
      1, 1e-5);
  // Radiometric: 100 cd is 100 / 683 W/sr of 555 nm light, or 400π / 683 W.
  EXPECT_NEAR(card_luminance(std::string(kPoint) + R"("intensity_w_sr": )" +
                             std::to_string(100 / 683.0) + "}") /
                  hand,
              1, 1e-5);
  EXPECT_NEAR(card_luminance(std::string(kPoint) + R"("power_w": )" +
                             std::to_string(400 * kPi / 683) + "}") /
                  hand,
              1, 1e-5);
  // White light of another spectrum: its own efficacy (e.g. 250 lm/W).
  EXPECT_NEAR(
      card_luminance(std::string(kPoint) + R"("intensity_w_sr": 0.4, "efficacy_lm_w": 250})") /
          hand,
      1, 1e-5);
}

TEST(LightUnits, SunInLuxAndWattsPerSquareMetre) {
  // 100 000 lux straight down: L = 0.5 · 1e5 / π.
  const double hand = 0.5 * 1e5 / kPi;
  EXPECT_NEAR(card_luminance(std::string(kSun) + R"("illuminance_lux": 100000})") / hand, 1, 1e-5);
  EXPECT_NEAR(card_luminance(std::string(kSun) + R"("irradiance": 100000})") / hand, 1, 1e-5);
  EXPECT_NEAR(card_luminance(std::string(kSun) + R"("irradiance_w_m2": )" +
                             std::to_string(1e5 / 683) + "}") /
                  hand,
              1, 1e-5);
}

TEST(LightUnits, GltfPunctualLightsInCandelaAndLux) {
  // KHR_lights_punctual: a point light of 100 cd 2 m above the origin and a 100 000 lux sun
  // shining down. Units are the scene's own, so the origin's illuminance is I/d² = 25 lux from the
  // bulb and 100 000 lux from the sun, by hand from the file's numbers.
  const test::json doc = test::json::parse(R"({
    "asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [
      {"type": "point", "intensity": 100}, {"type": "directional", "intensity": 100000}]}},
    "nodes": [{"translation": [0, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
              {"rotation": [-0.70710678, 0, 0, 0.70710678],
               "extensions": {"KHR_lights_punctual": {"light": 1}}}],
    "scenes": [{"nodes": [0, 1]}], "scene": 0})");
  const Scene scene = test::load_gltf_json(doc);
  ASSERT_EQ(scene.lights.size(), 2u);
  const auto& bulb = std::get<PointLight>(scene.lights[0].model);
  const double d2 = double(bulb.position.x) * bulb.position.x +
                    double(bulb.position.y) * bulb.position.y +
                    double(bulb.position.z) * bulb.position.z;
  EXPECT_NEAR(bulb.intensity.g / d2, 25, 1e-5);
  const auto& sun = std::get<DirectionalLight>(scene.lights[1].model);
  EXPECT_NEAR(sun.direction.y, -1, 1e-6);
  EXPECT_NEAR(sun.irradiance.g * -sun.direction.y, 100000, 1);
  // The JSON scene's same lights, in lumens and W/m², carry the same numbers.
  Scene json = load_json_scene_text(
      R"({"lights": [{"type": "point", "position": [0, 2, 0], "power_lm": 1256.6370614359172},
                     {"type": "directional", "direction": [0, -1, 0],
                      "irradiance_w_m2": 146.41288433382138}]})",
      "lights.json");
  EXPECT_NEAR(std::get<PointLight>(json.lights[0].model).intensity.g, bulb.intensity.g, 1e-3);
  EXPECT_NEAR(std::get<DirectionalLight>(json.lights[1].model).irradiance.g, sun.irradiance.g, 1);
}

TEST(LightUnits, OneStrengthPerLight) {
  const std::string message = test::error_of([] {
    std::string scene(kPoint);  // appended, not operator+: GCC 12's -Warray-bounds false positive
    scene += R"("intensity": 1, "power_lm": 3})";
    card_luminance(scene);
  });
  EXPECT_NE(message.find("give the light's strength once"), std::string::npos) << message;
}

}  // namespace
}  // namespace obscura

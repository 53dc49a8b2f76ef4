// Metering and automatic exposure against ISO 2720 and hand computations: a grey card filling
// the frame under a sun of known illuminance has luminance ρE/π, which an average meter reads
// as EV100 = log₂(L·S/K) with K = 12.5; the program's settings give that EV100 back; and a
// physical exposure at the metered settings records the card where the calibration puts it.
#include "obscura/render/auto_exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "obscura/io/json_scene.h"
#include "obscura/math/error.h"
#include "obscura/render/render_frame.h"

namespace obscura {
namespace {

// A 18 % grey Lambertian card filling the view of a camera looking straight down at it, lit by a
// sun of `lux` straight from above (the scene's irradiance unit is the lux in physical use).
Scene grey_card(double lux) {
  std::string text = R"({"materials": {"card": {"type": "diffuse", "reflectance": 0.18}},
          "objects": [{"name": "card", "shape": "rectangle", "size": [100, 100],
                       "material": "card"}],
          "lights": [{"name": "sun", "type": "directional", "direction": [0, -1, 0],
                      "irradiance": )";
  text += std::to_string(lux);
  text += R"(}],
          "cameras": [{"name": "c", "type": "perspective", "position": [0, 1, 0],
                       "target": [0, 0, 0], "up": [0, 0, -1], "focal_length_mm": 50}]})";
  Scene scene = load_json_scene_text(text, "card.json");
  scene.camera.film.width_px = 48;
  scene.camera.film.height_px = 32;
  return scene;
}

Image render(const Scene& scene, const Camera& camera) {
  FrameSettings settings;
  settings.samples_per_pixel = 1;
  return render_frame(scene, camera, settings, false).finished();
}

TEST(AutoExposure, GreyCardMetersTheIso2720Ev) {
  for (double lux : {100000.0, 400.0, 1.0}) {  // sunlight, an office, a night street
    const Scene scene = grey_card(lux);
    const Image film = render(scene, metering_camera(scene.camera));
    const double luminance = 0.18 * lux / std::numbers::pi;  // ρE/π, cd/m²
    const double iso2720 = std::log2(luminance * 100 / 12.5);
    for (MeteringMode mode :
         {MeteringMode::kAverage, MeteringMode::kCenterWeighted, MeteringMode::kSpot}) {
      const MeteredExposure m = meter_for(scene.camera, film, mode, 0);
      EXPECT_NEAR(m.ev100, iso2720, 1e-5) << lux << " lux, " << metering_mode_name(mode);
      // The program's settings give the metered EV100 back (to rounding).
      EXPECT_NEAR(ev100(m.settings.f_number, m.settings.exposure_time_s, m.settings.iso), m.ev100,
                  1e-9);
    }
  }
}

TEST(AutoExposure, ExposesTheCardAtTheMeteredLevel) {
  // At the metered settings the physical exposure records L·t·S/(120·N²) = 12.5/120 of the
  // saturating level for the metered luminance, whatever the light: the card lands at 0.104
  // in sunlight, the office and the night street alike (within a third of a stop: exactly here).
  for (double lux : {100000.0, 400.0, 1.0}) {
    Scene scene = grey_card(lux);
    const MeteredExposure m = meter_for(scene.camera, render(scene, metering_camera(scene.camera)),
                                        MeteringMode::kAverage, 0);
    apply_exposure(scene.camera, m.settings);
    const Image exposed = render(scene, scene.camera);
    EXPECT_NEAR(exposed.at(24, 16, 1), 12.5 / 120, 1e-5) << lux;
    // One stop of compensation doubles it.
    Scene brighter = grey_card(lux);
    const MeteredExposure plus =
        meter_for(brighter.camera, render(brighter, metering_camera(brighter.camera)),
                  MeteringMode::kAverage, 1);
    apply_exposure(brighter.camera, plus.settings);
    EXPECT_NEAR(render(brighter, brighter.camera).at(24, 16, 1), 2 * 12.5 / 120, 2e-5) << lux;
  }
}

TEST(AutoExposure, ProgramFollowsItsLine) {
  // Sunny 16's EV100 15 splits evenly, Av = Tv = 7.5: f/13.5 at 1/181 s, ISO 100.
  ExposureSettings s = program_exposure(15);
  EXPECT_NEAR(ev100(s.f_number, s.exposure_time_s, s.iso), 15, 1e-12);
  EXPECT_EQ(s.iso, 100);
  EXPECT_NEAR(s.f_number, std::exp2(15.0 / 4), 1e-9);
  // A dark room (EV100 2): f/1.4, 1/30 s, and the ISO raised to make up the rest.
  s = program_exposure(2);
  EXPECT_NEAR(s.f_number, std::sqrt(2.0), 1e-9);  // f/1.4, as the exposure counts it
  EXPECT_NEAR(s.exposure_time_s, 1.0 / 30, 1e-12);
  EXPECT_GT(s.iso, 100);
  EXPECT_NEAR(ev100(s.f_number, s.exposure_time_s, s.iso), 2, 1e-12);
  // A fixed iris: shutter and ISO only.
  s = program_exposure(12, 5.6);
  EXPECT_NEAR(s.f_number, 5.6, 1e-12);
  EXPECT_NEAR(ev100(s.f_number, s.exposure_time_s, s.iso), 12, 1e-12);
}

TEST(AutoExposure, BlackFrameIsAnError) {
  Scene scene = grey_card(1);
  EXPECT_THROW(meter_for(scene.camera, Image(8, 8, 3), MeteringMode::kAverage, 0), Error);
}

}  // namespace
}  // namespace obscura

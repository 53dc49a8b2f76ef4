// The lens-system camera of the JSON scene file: a built-in lens or a prescription file next to
// the scene, its f-number and focus arrive in the camera, and mistakes name the JSON path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "obscura/camera/builtin_lenses.h"
#include "obscura/io/json_scene.h"
#include "obscura/math/error.h"

namespace obscura {
namespace {

Scene load(const std::string& camera, const std::string& file = "scene.json") {
  return load_json_scene_text(
      R"({"render": {"width": 96, "height": 64}, "cameras": [)" + camera + "]}", file);
}

TEST(LensSystemCameraJson, KeysArriveInTheCamera) {
  Scene s = load(R"({"type": "lens_system", "lens": "double-gauss-50mm", "position": [0, 0, 3],
    "target": [0, 0, 0], "f_number": 4, "sensor_width_mm": 24, "aperture_blades": 7})");
  const auto& p = std::get<LensSystemProjection>(s.camera.projection);
  EXPECT_EQ(p.lens, builtin_lens("double-gauss-50mm"));
  EXPECT_EQ(p.f_number, 4);
  EXPECT_EQ(p.sensor_width_mm, 24);
  EXPECT_EQ(s.camera.lens.aperture.blades, 7);
  EXPECT_EQ(s.camera.lens.focus_distance_m, 3);  // the target's distance, from the sensor
  EXPECT_FALSE(s.camera.lens.depth_of_field);    // the lens's own, not the thin lens's
  EXPECT_EQ(s.camera.f_number(), 4);
}

TEST(LensSystemCameraJson, PrescriptionFileIsRelativeToTheScene) {
  auto folder = std::filesystem::temp_directory_path() / "obscura_lens_json_test";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "singlet.tsv") << "0 1 0 10\n60 4 1.5168 30 64.17\n-60 0 1 30\n";
  Scene s = load(R"({"type": "lens_system", "lens_file": "singlet.tsv"})",
                 (folder / "scene.json").string());
  const auto& p = std::get<LensSystemProjection>(s.camera.projection);
  EXPECT_EQ(p.lens->name(), "singlet");
  EXPECT_EQ(p.lens->prescription().surfaces[1].abbe_number, 64.17);
  std::filesystem::remove_all(folder);
}

TEST(LensSystemCameraJson, MistakesNameThePath) {
  auto error_of = [](const std::string& camera) -> std::string {
    try {
      load(camera);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of(R"({"type": "lens_system"})").find("$.cameras[0].lens"), std::string::npos);
  EXPECT_NE(error_of(R"({"type": "lens_system", "lens": "zoom"})").find("double-gauss-50mm"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"type": "lens_system", "lens_file": "missing.tsv"})")
                .find("$.cameras[0].lens_file"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"type": "lens_system", "lens": "double-gauss-50mm", "f_number": 1.4})")
                .find("f_number"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"type": "lens_system", "lens": "telephoto-250mm",
                         "position": [0, 0, 0.5], "target": [0, 0, 0]})")
                .find("cannot focus"),
            std::string::npos);
}

TEST(LensSystemCameraJson, CoatingAndFlareArrive) {
  Scene s = load(R"({"type": "lens_system", "lens": "double-gauss-50mm", "coating": "none"})");
  EXPECT_FALSE(std::get<LensSystemProjection>(s.camera.projection).coating.coated());
  s = load(R"({"type": "lens_system", "lens": "double-gauss-50mm",
               "coating": "quarter-wave:1.25:500"})");
  EXPECT_EQ(std::get<LensSystemProjection>(s.camera.projection).coating,
            quarter_wave_coating(1.25, 500));
  // The default: single-coated (MgF2 at 550 nm).
  s = load(R"({"type": "lens_system", "lens": "double-gauss-50mm"})");
  EXPECT_EQ(std::get<LensSystemProjection>(s.camera.projection).coating, quarter_wave_coating());
  Scene flare = load_json_scene_text(R"({"render": {"flare": true}})", "scene.json");
  EXPECT_EQ(flare.render.flare, true);
}

TEST(LensSystemCameraJson, CoatingAndFlareMistakesNameTheField) {
  auto error_of = [](const std::string& text) -> std::string {
    try {
      load_json_scene_text(text, "scene.json");
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  const std::string bad_coating = error_of(
      R"({"cameras": [{"type": "lens_system", "lens": "double-gauss-50mm", "coating": "wax"}]})");
  EXPECT_NE(bad_coating.find("$.cameras[0].coating"), std::string::npos) << bad_coating;
  EXPECT_NE(bad_coating.find("quarter-wave"), std::string::npos) << bad_coating;
  EXPECT_NE(error_of(R"({"cameras": [{"type": "lens_system", "lens": "double-gauss-50mm",
                                       "coating": 3}]})")
                .find("coating"),
            std::string::npos);
  const std::string bad_flare = error_of(R"({"render": {"flare": "yes"}})");
  EXPECT_NE(bad_flare.find("flare"), std::string::npos) << bad_flare;
}

}  // namespace
}  // namespace obscura

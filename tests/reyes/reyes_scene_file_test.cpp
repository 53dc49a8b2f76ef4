// REYES's knobs in a scene file (`render.reyes`, docs/scene-format.md): the values reach the
// renderer — checked by what they must do to its counts (the shading rate is the micropolygon
// area, RenderMan's definition; every covered visibility sample is hit once) — the caller's
// options win over them, and bad values are refused naming the field.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "obscura/io/json_scene.h"
#include "obscura/math/error.h"
#include "obscura/render/frame_request.h"
#include "obscura/render/render_frame.h"
#include "obscura/render/renderer.h"

namespace obscura {
namespace {

// A square facing the camera head-on, filling about a third of a 64 × 64 frame; `reyes` is the
// render.reyes block's JSON.
std::string square_scene(const std::string& reyes) {
  std::string text = R"({
    "render": {"width": 64, "height": 64, "reyes": )";
  text += reyes;
  text += R"(},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"shape": "rectangle", "size": [1, 1], "material": "white",
                 "transform": {"rotate_degrees": [90, 0, 0]}}],
    "lights": [{"type": "directional", "direction": [0, 0, -1], "irradiance": 1}],
    "cameras": [{"position": [0, 0, 1.8], "target": [0, 0, 0], "fov_degrees": 40}]
  })";
  return text;
}

// The counter `name` of a REYES frame's --stats lines.
double counter(const FrameStats& stats, const std::string& name) {
  for (const std::string& line : stats.details)
    if (line.rfind(name + ": ", 0) == 0) return std::stod(line.substr(name.size() + 2));
  ADD_FAILURE() << "no counter " << name;
  return 0;
}

FrameStats render_with(const Scene& scene, const FrameRequest& request) {
  const Renderer reyes = renderer_named("reyes");
  FrameSettings settings{.renderer = reyes};
  settings.reyes = resolve_frame_request(request, scene.render, reyes).reyes;
  return render_frame(scene, scene.camera, settings, false).stats;
}

TEST(ReyesSceneFile, ReadsTheKnobsAndTheCallersOptionsWin) {
  const Scene scene =
      load_json_scene_text(square_scene(R"({"shading_rate": 4, "grid_size": 64, "bucket_size": 8,
                       "pixel_samples": 2, "eye_splits": 3})"),
                           "knobs.json");
  const Renderer reyes = renderer_named("reyes");
  const reyes::ReyesSettings file = resolve_frame_request({}, scene.render, reyes).reyes;
  EXPECT_EQ(file.shading_rate, 4);
  EXPECT_EQ(file.grid_size, 64);
  EXPECT_EQ(file.bucket_size, 8);
  EXPECT_EQ(file.pixel_samples, 2);
  EXPECT_EQ(file.eye_splits, 3);
  // The caller's option wins over the file's for that knob alone.
  const reyes::ReyesSettings caller =
      resolve_frame_request({.reyes_shading_rate = 0.5}, scene.render, reyes).reyes;
  EXPECT_EQ(caller.shading_rate, 0.5);
  EXPECT_EQ(caller.bucket_size, 8);
  // No block: the renderer's defaults.
  const Scene plain = load_json_scene_text(square_scene("{}"), "plain.json");
  const reyes::ReyesSettings none = resolve_frame_request({}, plain.render, reyes).reyes;
  const reyes::ReyesSettings defaults;
  EXPECT_EQ(none.shading_rate, defaults.shading_rate);
  EXPECT_EQ(none.pixel_samples, defaults.pixel_samples);
}

// The file's shading rate of 4 dices a quarter of the micropolygons a rate of 1 does (area per
// micropolygon, ±25 %), its grid size caps every grid, and its 2 pixel samples hit a quarter of
// the samples 8 do (each covered sample is hit exactly once).
TEST(ReyesSceneFile, TheFilesKnobsReachTheRenderer) {
  const Scene scene = load_json_scene_text(
      square_scene(R"({"shading_rate": 4, "grid_size": 16, "pixel_samples": 2})"), "knobs.json");
  const FrameStats file = render_with(scene, {});
  const FrameStats fine = render_with(scene, {.reyes_shading_rate = 1, .reyes_pixel_samples = 8});
  const double ratio = counter(fine, "reyes micropolygons") / counter(file, "reyes micropolygons");
  EXPECT_NEAR(ratio, 4, 1);
  RecordProperty("micropolygon_ratio", std::to_string(ratio));
  EXPECT_LE(counter(file, "reyes micropolygons"), 16 * counter(file, "reyes grids"));
  EXPECT_LE(counter(fine, "reyes micropolygons"), 16 * counter(fine, "reyes grids"));
  const double hits = counter(fine, "reyes samples hit") / counter(file, "reyes samples hit");
  EXPECT_NEAR(hits, 4, 0.2);
  RecordProperty("samples_hit_ratio", std::to_string(hits));
  EXPECT_LE(counter(file, "reyes micropolygon area max (px)"), 4.0);
}

TEST(ReyesSceneFile, RefusesBadKnobsNamingTheField) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> bad = {
      {"shading_rate", {"0", "-1", "1e-9", "1e9", "\"fine\"", "true", "null", "[1]"}},
      {"grid_size", {"0", "-1", "1000000000", "1e9", "2.5", "\"big\""}},
      {"bucket_size", {"0", "-16", "65", "1e9", "16.5", "false"}},
      {"pixel_samples", {"0", "-1", "4097", "1e9", "\"16\""}},
      {"eye_splits", {"-1", "33", "1e9", "0.5", "{}"}}};
  for (const auto& [field, values] : bad)
    for (const std::string& value : values) {
      const std::string block = "{\"" + field + "\": " + value + "}";
      try {
        load_json_scene_text(square_scene(block), "bad.json");
        ADD_FAILURE() << block << " was accepted";
      } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("bad.json"), std::string::npos) << message;
        EXPECT_NE(message.find("$.render.reyes." + field), std::string::npos) << message;
      }
    }
  // An unknown knob (a typo) is refused by its name too.
  EXPECT_THROW(load_json_scene_text(square_scene(R"({"shading_rat": 2})"), "typo.json"), Error);
}

}  // namespace
}  // namespace obscura

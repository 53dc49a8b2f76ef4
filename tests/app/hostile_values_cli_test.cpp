// Values that parse fine but once broke rendering (issue 32), run as a user would: each is
// refused with exit 1 (a file's value) or 2 (an option's) and a message naming the field, or
// renders; never a signal (SIGSEGV from NaN table indices or a missing environment light,
// SIGABRT from Embree's assertion on coordinates beyond ~1.8e18), never an output file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class HostileValuesCli : public test::TempDirTest {
 protected:
  struct Case {
    std::string arguments;  // after `render -q --width 16 --height 12 --spp 1`
    int exit_code;
    std::vector<std::string> expected;  // pieces of the message
  };

  // Runs every case with both renderers, side by side.
  void expect_cases(const std::vector<Case>& cases) {
    std::vector<std::string> lines;
    std::vector<std::string> outputs;
    for (const Case& c : cases)
      for (const char* renderer : {"path", "raster"}) {
        outputs.push_back(path(std::string("out_") + std::to_string(lines.size()) + ".png"));
        lines.push_back(test::cli_command_line(
            "render -q --width 16 --height 12 --spp 1 "
            "--renderer " +
            std::string(renderer) + " " + c.arguments + " -o " + outputs.back()));
      }
    std::vector<test::CommandResult> results = test::run_shells_concurrently(lines);
    for (size_t i = 0; i < results.size(); ++i) {
      const Case& c = cases[i / 2];
      const std::string what = c.arguments + (i % 2 ? " (raster)" : " (path)");
      EXPECT_EQ(results[i].exit_code, c.exit_code) << what << "\n" << results[i].output;
      for (const std::string& piece : c.expected)
        EXPECT_NE(results[i].output.find(piece), std::string::npos)
            << what << ": expected '" << piece << "' in\n"
            << results[i].output;
      if (c.exit_code != 0) {
        EXPECT_FALSE(fs::exists(outputs[i])) << what;
      }
    }
  }

  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }

  // A JSON scene: a grey floor under a point light, seen by one camera; `camera`, `transform`
  // and `light_position` as JSON text.
  std::string scene(const std::string& name, const std::string& camera_extra = "",
                    const std::string& transform = "{\"translate\": [0, 0, 0]}",
                    const std::string& light_position = "[0, 2, 0]") {
    return write(name,
                 "{\"materials\": {\"grey\": {\"type\": \"diffuse\", \"reflectance\": 0.5}},\n"
                 " \"objects\": [{\"name\": \"floor\", \"shape\": \"rectangle\", \"size\": [4, "
                 "4], \"material\": \"grey\", \"transform\": " +
                     transform +
                     "}],\n"
                     " \"lights\": [{\"name\": \"bulb\", \"type\": \"point\", \"position\": " +
                     light_position +
                     ", \"intensity\": 5}],\n"
                     " \"cameras\": [{\"name\": \"c\", \"type\": \"perspective\", \"position\": "
                     "[0, 2, 6], \"target\": [0, 0, 0]" +
                     camera_extra + "}]}\n");
  }
};

TEST_F(HostileValuesCli, CameraOptionsInsideTheirRangesAreRefusedNotAborted) {
  expect_cases({
      {"--focal-length 1e-20", 2, {"camera.focal_length_mm", "1e-20"}},
      {"--fstop 1e-300", 2, {"camera.f_number", "aperture"}},
      {"--sensor 1e300x1e300", 2, {"camera.sensor_mm", "1e+300"}},
      {"--projection orthographic --view-height 1e12", 2, {"--view-height", "1e12"}},
      // Within the option's range, but 16:12 makes the view 2.5e7 m wide.
      {"--projection orthographic --view-height 1.9e7", 2, {"camera.view_height_m"}},
  });
}

TEST_F(HostileValuesCli, SceneCoordinatesBeyondTheBoundNameTheField) {
  expect_cases({
      {scene("camera.json", ", \"motion\": [{\"time\": 0, \"position\": [2e18, 2, 6]}]"),
       1,
       {"camera.json", "camera.position", "single-precision"}},
      {scene("shift.json", ", \"lens_shift\": [1e20, 0]"), 1, {"camera.lens_shift"}},
      {scene("scale.json", "", "{\"scale\": 1e18}"),
       1,
       {"instance 'floor'", "world_from_object", "single-precision"}},
      {scene("translate.json", "", "{\"translate\": [-1e308, 0, 0]}"),
       1,
       {"instance 'floor'", "-1e+308"}},
      {scene("light.json", "", "{\"translate\": [0, 0, 0]}", "[1e308, 0, 0]"),
       1,
       {"light 'bulb'", "position"}},
  });
}

TEST_F(HostileValuesCli, GltfEmissiveStrengthBeyondTheBoundIsRefused) {
  // One emissive triangle; KHR_materials_emissive_strength 1e38 made its power inf, the light
  // selection's CDF NaN, and the tracer sampled a missing environment light.
  const std::string triangle = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";  // 3 × vec3
  std::string gltf =
      R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_emissive_strength"],
 "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" +
      triangle + R"("}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "materials": [{"name": "lamp", "emissiveFactor": [1, 1, 1],
                "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e38}}}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
 "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  expect_cases({{write("lamp.gltf", gltf), 1, {"material 'lamp'", "emission"}}});
}

TEST_F(HostileValuesCli, NanTextureAsMetallicRoughnessRenders) {
  // A 2 × 2 PFM of NaN as the metallic-roughness texture: NaN roughness once indexed the GGX
  // energy tables at INT_MIN (SIGSEGV in both renderers). Now the reader replaces the NaN texels
  // (by 0; tests/io/texture_values_test.cpp checks the warning naming the file).
  std::string pfm = "PF\n2 2\n-1.0\n";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 12; ++i) pfm.append(reinterpret_cast<const char*>(&nan), sizeof nan);
  write("nan.pfm", pfm);
  std::string json = write(
      "nan.json",
      "{\"materials\": {\"m\": {\"type\": \"metallic-roughness\", \"metallic\": 0.5, "
      "\"roughness\": 0.5, \"metallic_roughness_texture\": \"nan.pfm\"}},\n"
      " \"objects\": [{\"name\": \"floor\", \"shape\": \"rectangle\", \"size\": [4, 4], "
      "\"material\": \"m\"}],\n"
      " \"lights\": [{\"name\": \"bulb\", \"type\": \"point\", \"position\": [0, 2, 0]}],\n"
      " \"cameras\": [{\"type\": \"perspective\", \"position\": [0, 2, 6], \"target\": [0, 0, "
      "0]}]}\n");
  expect_cases({{json, 0, {}}});
}

TEST_F(HostileValuesCli, CalibrationsBeyondTheBoundOrImagingNothingAreRefused) {
  const std::string yaml =
      "%YAML:1.0\n---\nimage_width: 16\nimage_height: 12\n"
      "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
      "   data: [ FX, 0, 8, 0, 20, 6, 0, 0, 1 ]\n"
      "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n"
      "   data: [ K1, 0.01, 0, 0, 0 ]\n"
      "R: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
      "   data: [ -1, 0, 0, 0, -1, 0, 0, 0, 1 ]\n"
      "T: !!opencv-matrix\n   rows: 3\n   cols: 1\n   dt: d\n   data: [ TX, 0.273, 0.8 ]\n";
  auto calibration = [&](const std::string& name, const std::string& fx, const std::string& k1,
                         const std::string& tx) {
    std::string text = yaml;
    text.replace(text.find("FX"), 2, fx);
    text.replace(text.find("K1"), 2, k1);
    text.replace(text.find("TX"), 2, tx);
    return "--calibration " + write(name, text);
  };
  const std::string nerf =
      "{\"camera_angle_x\": 6.3, \"w\": 16, \"h\": 12, \"frames\": [{\"file_path\": \"a\", "
      "\"transform_matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}]}";
  expect_cases({
      {calibration("ok.yaml", "20", "-0.1", "0.278"), 0, {}},
      {calibration("far.yaml", "20", "-0.1", "2e18"),
       1,
       {"far.yaml", "camera position", "2e+18", "single-precision"}},
      {calibration("fx.yaml", "1e-300", "-0.1", "0.278"),
       1,
       {"fx.yaml", "camera.intrinsics.fx", "images nothing"}},
      {calibration("k1.yaml", "20", "1e300", "0.278"), 1, {"k1.yaml", "camera.lens.k1"}},
      {"--calibration " + write("transforms.json", nerf), 1, {"transforms.json", "camera_angle_x"}},
  });
}

}  // namespace
}  // namespace obscura

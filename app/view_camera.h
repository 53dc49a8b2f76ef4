// The camera the live view's page handles (`obscura view`, docs/view.md), and how it becomes an
// `obscura render` command line. The page never names a file or a renderer: it moves the camera
// (position, the point it looks at, up), sets the focal length, f-number, focus distance and
// exposure compensation. The server renders exactly what the command line it offers under "copy
// camera" would: both parse the same arguments (view_command.cpp), so pasting them into
// `obscura render` gives the viewed frame bit for bit.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"

namespace obscura::app {

struct ViewCamera {
  bool placed = false;  // position, target and up are the page's; else the scene camera's pose
  std::array<double, 3> position = {0, 0, 0};
  std::array<double, 3> target = {0, 0, -1};
  std::array<double, 3> up = {0, 1, 0};
  std::optional<double> focal_length_mm = std::nullopt;
  std::optional<double> f_number = std::nullopt;
  std::optional<double> focus_distance_m = std::nullopt;
  std::optional<double> exposure_ev = std::nullopt;
  std::optional<double> shutter_s = std::nullopt;  // open from 0 for this long
  std::optional<double> iso = std::nullopt;
  std::optional<bool> physical_exposure = std::nullopt;  // --exposure-mode physical / radiance
  // "thin" (the thin lens, replacing a --lens given) or a built-in lens system's name.
  std::optional<std::string> lens = std::nullopt;
  std::optional<std::string> sensor = std::nullopt;          // "WxH" in mm
  std::optional<std::array<int, 2>> size_px = std::nullopt;  // the film: the frame's aspect
};

// The page's JSON ({"position": [x, y, z], "target": …, "up": …, "focal_length_mm": 35,
// "f_number": 2.8 or null, "focus_distance_m": …, "exposure_ev": …, "shutter_s": …, "iso": …,
// "physical_exposure": true or false, "lens": "thin" or a built-in lens system's name, "sensor":
// "36x24", "size": [width, height]}; every key optional, absent
// ones kept from `current`). Throws RequestError for malformed JSON, an unknown key, a value of the
// wrong type, not finite or out of range.
ViewCamera parse_view_camera(const std::string& text, const ViewCamera& current);

// The camera as the page reads it back, with what the resolved camera adds (the field of view).
std::string view_camera_json(const ViewCamera& view, const Camera& resolved);

// The view's starting camera: the resolved camera's pose at the shutter's opening, looking at a
// point `target_distance_m` ahead (the page orbits about it).
ViewCamera initial_view_camera(const Camera& camera, double target_distance_m);

// Removes from `arguments` (an `obscura view` command line after the word `view`) the view's own
// options (--port, --open, --no-watch) and the camera options `view` overrides, then appends the
// overrides: the `obscura render` arguments for the viewed frame.
std::vector<std::string> render_arguments(const std::vector<std::string>& arguments,
                                          const ViewCamera& view);

// "obscura render ARG …", each argument quoted for a POSIX shell where it needs it.
std::string shell_command(const std::vector<std::string>& render_arguments);

// The camera as a JSON scene file's "cameras" entry (docs/scene-format.md), for a perspective
// camera; empty for another projection.
std::string scene_camera_json(const Camera& camera, const ViewCamera& view);

// A double written so that reading it back gives the same double ("%.17g", trimmed).
std::string exact_number(double value);

}  // namespace obscura::app

#include "view_camera.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string_view>

#include <nlohmann/json.hpp>

#include "obscura/math/request_error.h"
#include "obscura/math/value_limits.h"
#include "option_ranges.h"

namespace obscura::app {

namespace {

using Json = nlohmann::json;

// The ranges the page may ask for: those of the matching command-line options, narrowed where a
// value would only make a frame nobody could look at.
constexpr double kMinFocalLengthMm = 1, kMaxFocalLengthMm = 5000;
constexpr double kMinFNumber = 0.5, kMaxFNumber = 1024;
constexpr double kMinFocusDistanceM = 1e-3;
constexpr double kMinShutterS = 1e-6, kMaxShutterS = 60;
constexpr double kMinIso = 1, kMaxIso = 1e6;

double json_number_in(const Json& value, const char* key, double low, double high) {
  if (!value.is_number()) throw RequestError(std::string("camera.") + key, "expected a number");
  const double v = value.get<double>();
  if (!std::isfinite(v) || v < low || v > high)
    throw RequestError(std::string("camera.") + key, "expected a number in [" + exact_number(low) +
                                                         ", " + exact_number(high) + "]");
  return v;
}

std::array<double, 3> point_of(const Json& value, const char* key) {
  if (!value.is_array() || value.size() != 3)
    throw RequestError(std::string("camera.") + key, "expected [x, y, z]");
  return {json_number_in(value[0], key, -kMaxWorldCoordinateM, kMaxWorldCoordinateM),
          json_number_in(value[1], key, -kMaxWorldCoordinateM, kMaxWorldCoordinateM),
          json_number_in(value[2], key, -kMaxWorldCoordinateM, kMaxWorldCoordinateM)};
}

// null clears an optional setting (back to the scene's camera); a number sets it.
std::optional<double> optional_in(const Json& value, const char* key, double low, double high) {
  if (value.is_null()) return std::nullopt;
  return json_number_in(value, key, low, high);
}

std::string triple(const std::array<double, 3>& v) {
  return exact_number(v[0]) + "," + exact_number(v[1]) + "," + exact_number(v[2]);
}

Json array_of(const std::array<double, 3>& v) {
  return Json::array({v[0], v[1], v[2]});
}

// Options `obscura view` has and `obscura render` has not; their values come after them.
const std::set<std::string> kViewOnlyWithValue = {"--port", "--max-requests-per-second", "-o",
                                                  "--output"};
const std::set<std::string> kViewOnlyFlags = {"--open", "--no-watch"};

// The lenses the page offers: no file is named from the page.
const std::set<std::string> kLenses = {"thin", "double-gauss-50mm", "telephoto-250mm",
                                       "fisheye-10mm"};

}  // namespace

std::string exact_number(double value) {
  // 17 significant digits always read back as the same double; fewer often do, and are kept
  // when they do so that the command line stays readable.
  char text[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

ViewCamera parse_view_camera(const std::string& text, const ViewCamera& current) {
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::exception&) {
    throw RequestError("camera", "expected a JSON object");
  }
  if (!json.is_object()) throw RequestError("camera", "expected a JSON object");
  ViewCamera view = current;
  bool moved = false;
  for (const auto& [key, value] : json.items()) {
    if (key == "position") {
      view.position = point_of(value, "position");
      moved = true;
    } else if (key == "target") {
      view.target = point_of(value, "target");
      moved = true;
    } else if (key == "up") {
      view.up = point_of(value, "up");
      moved = true;
    } else if (key == "focal_length_mm") {
      view.focal_length_mm =
          optional_in(value, "focal_length_mm", kMinFocalLengthMm, kMaxFocalLengthMm);
    } else if (key == "f_number") {
      view.f_number = optional_in(value, "f_number", kMinFNumber, kMaxFNumber);
    } else if (key == "focus_distance_m") {
      view.focus_distance_m =
          optional_in(value, "focus_distance_m", kMinFocusDistanceM, kMaxWorldCoordinateM);
    } else if (key == "exposure_ev") {
      view.exposure_ev = optional_in(value, "exposure_ev", -kMaxExposureEv, kMaxExposureEv);
    } else if (key == "shutter_s") {
      view.shutter_s = optional_in(value, "shutter_s", kMinShutterS, kMaxShutterS);
    } else if (key == "iso") {
      view.iso = optional_in(value, "iso", kMinIso, kMaxIso);
    } else if (key == "lens") {
      if (value.is_null()) {
        view.lens.reset();
      } else {
        const std::string name = value.is_string() ? value.get<std::string>() : "";
        if (!kLenses.count(name))
          throw RequestError("camera.lens",
                             "expected null, thin, double-gauss-50mm, "
                             "telephoto-250mm or fisheye-10mm");
        view.lens = name;
      }
    } else if (key == "sensor") {
      if (value.is_null()) {
        view.sensor.reset();
      } else {
        double w = 0, h = 0;
        char x = 0, rest = 0;
        const std::string text = value.is_string() ? value.get<std::string>() : "";
        if (text.size() > 16 || std::sscanf(text.c_str(), "%lf%c%lf%c", &w, &x, &h, &rest) != 3 ||
            x != 'x' || !(w >= 1 && w <= 100 && h >= 1 && h <= 100))
          throw RequestError("camera.sensor", "expected \"WxH\" in mm, each 1 to 100");
        view.sensor = exact_number(w) + "x" + exact_number(h);
      }
    } else if (key == "size") {
      if (value.is_null()) {
        view.size_px.reset();
      } else {
        if (!value.is_array() || value.size() != 2 || !value[0].is_number_integer() ||
            !value[1].is_number_integer())
          throw RequestError("camera.size", "expected [width, height] in pixels");
        const int64_t w = value[0].get<int64_t>(), h = value[1].get<int64_t>();
        if (w < 16 || h < 16 || w > 4096 || h > 4096)
          throw RequestError("camera.size", "expected each side from 16 to 4096 pixels");
        view.size_px = std::array<int, 2>{int(w), int(h)};
      }
    } else if (key == "physical_exposure") {
      if (!value.is_null() && !value.is_boolean())
        throw RequestError("camera.physical_exposure", "expected true, false or null");
      view.physical_exposure =
          value.is_null() ? std::nullopt : std::optional<bool>(value.get<bool>());
    } else {
      throw RequestError("camera", "unknown key '" + key + "'");
    }
  }
  if (moved) view.placed = true;
  return view;
}

std::string view_camera_json(const ViewCamera& view, const Camera& resolved) {
  Json json = {{"placed", view.placed},
               {"position", array_of(view.position)},
               {"target", array_of(view.target)},
               {"up", array_of(view.up)}};
  auto optional = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
  json["focal_length_mm"] = optional(view.focal_length_mm);
  json["f_number"] = optional(view.f_number);
  json["focus_distance_m"] = optional(view.focus_distance_m);
  json["exposure_ev"] = optional(view.exposure_ev);
  json["shutter_s"] = optional(view.shutter_s);
  json["iso"] = optional(view.iso);
  json["physical_exposure"] =
      view.physical_exposure ? Json(*view.physical_exposure) : Json(nullptr);
  json["lens"] = view.lens ? Json(*view.lens) : Json(nullptr);
  json["sensor"] = view.sensor ? Json(*view.sensor) : Json(nullptr);
  json["size"] =
      view.size_px ? Json::array({(*view.size_px)[0], (*view.size_px)[1]}) : Json(nullptr);
  // What the resolved camera has, for the page's read-outs.
  const Vector2d fov = resolved.fov_degrees();
  json["resolved"] = {
      {"focal_length_mm", resolved.focal_length_mm()},
      {"fov_degrees", Json::array({fov.x, fov.y})},
      {"f_number", resolved.f_number()},
      {"depth_of_field", resolved.lens.depth_of_field},
      {"focus_distance_m", resolved.lens.focus_distance_m},
      {"exposure_ev", resolved.exposure.compensation_ev},
      {"shutter_s", resolved.shutter.duration_s()},
      {"iso", resolved.exposure.iso},
      {"physical_exposure", resolved.exposure.mode == ExposureMode::physical},
      {"projection", std::string(projection_name(resolved.projection))},
      {"sensor_mm", Json::array({resolved.film_size_mm().x, resolved.film_size_mm().y})},
      {"width", resolved.film.width_px},
      {"height", resolved.film.height_px}};
  return json.dump();
}

ViewCamera initial_view_camera(const Camera& camera, double target_distance_m) {
  const Transform pose = camera.world_from_camera.at(camera.shutter.open_s);
  const Point3d eye = pose(Point3d(0, 0, 0));
  const Vector3d forward = normalize(pose(Vector3d(0, 0, -1)));
  const Vector3d up = normalize(pose(Vector3d(0, 1, 0)));
  const Point3d target = eye + forward * target_distance_m;
  return {.placed = false,
          .position = {eye.x, eye.y, eye.z},
          .target = {target.x, target.y, target.z},
          .up = {up.x, up.y, up.z},
          .focal_length_mm = std::nullopt,
          .f_number = std::nullopt,
          .focus_distance_m = std::nullopt,
          .exposure_ev = std::nullopt,
          .shutter_s = std::nullopt,
          .iso = std::nullopt,
          .physical_exposure = std::nullopt,
          .lens = std::nullopt,
          .sensor = std::nullopt,
          .size_px = std::nullopt};
}

std::vector<std::string> render_arguments(const std::vector<std::string>& arguments,
                                          const ViewCamera& view) {
  // The camera options the view sets replace the ones given, which would otherwise be given
  // twice (CLI11 refuses that) or contradict (--fov beside --focal-length).
  std::set<std::string> replaced;
  if (view.placed) replaced.insert({"--position", "--look-at", "--up"});
  if (view.focal_length_mm) replaced.insert({"--focal-length", "--fov", "--hfov"});
  if (view.f_number) replaced.insert("--fstop");
  if (view.focus_distance_m) replaced.insert("--focus-distance");
  if (view.exposure_ev) replaced.insert("--exposure");
  if (view.shutter_s) replaced.insert("--shutter");
  if (view.iso) replaced.insert("--iso");
  if (view.physical_exposure) replaced.insert("--exposure-mode");
  if (view.lens) replaced.insert({"--lens", "--lens-file"});
  if (view.sensor) replaced.insert("--sensor");
  if (view.size_px) replaced.insert({"--width", "--height"});
  std::vector<std::string> out;
  for (size_t i = 0; i < arguments.size(); ++i) {
    const std::string& a = arguments[i];
    const size_t equals = a.find('=');
    const std::string name = a.rfind("--", 0) == 0 ? a.substr(0, equals) : a;
    const bool inline_value = a.rfind("--", 0) == 0 && equals != std::string::npos;
    if (a.size() > 2 && a.rfind("-o", 0) == 0 && a[1] == 'o' && a.rfind("--", 0) != 0)
      continue;  // -oFILE
    if (kViewOnlyFlags.count(name)) continue;
    if (kViewOnlyWithValue.count(name) || replaced.count(name)) {
      if (!inline_value) ++i;  // its value
      continue;
    }
    out.push_back(a);
  }
  if (view.placed) {
    out.insert(out.end(), {"--position", triple(view.position), "--look-at", triple(view.target),
                           "--up", triple(view.up)});
  }
  if (view.focal_length_mm)
    out.insert(out.end(), {"--focal-length", exact_number(*view.focal_length_mm)});
  if (view.f_number) out.insert(out.end(), {"--fstop", exact_number(*view.f_number)});
  if (view.focus_distance_m)
    out.insert(out.end(), {"--focus-distance", exact_number(*view.focus_distance_m)});
  if (view.exposure_ev) out.insert(out.end(), {"--exposure", exact_number(*view.exposure_ev)});
  if (view.shutter_s) out.insert(out.end(), {"--shutter", "0:" + exact_number(*view.shutter_s)});
  if (view.iso) out.insert(out.end(), {"--iso", exact_number(*view.iso)});
  if (view.physical_exposure)
    out.insert(out.end(), {"--exposure-mode", *view.physical_exposure ? "physical" : "radiance"});
  if (view.lens && *view.lens != "thin") out.insert(out.end(), {"--lens", *view.lens});
  if (view.sensor) out.insert(out.end(), {"--sensor", *view.sensor});
  if (view.size_px)
    out.insert(out.end(), {"--width", std::to_string((*view.size_px)[0]), "--height",
                           std::to_string((*view.size_px)[1])});
  return out;
}

std::string shell_command(const std::vector<std::string>& arguments) {
  std::string command = "obscura render";
  for (const std::string& a : arguments) {
    bool plain = !a.empty();
    for (char c : a)
      plain = plain && (std::isalnum(static_cast<unsigned char>(c)) ||
                        std::string_view("_./:,=+-@%").find(c) != std::string_view::npos);
    command += ' ';
    if (plain) {
      command += a;
    } else {
      command += '\'';
      for (char c : a) command += c == '\'' ? std::string("'\\''") : std::string(1, c);
      command += '\'';
    }
  }
  return command;
}

std::string scene_camera_json(const Camera& camera, const ViewCamera& view) {
  const auto* perspective = std::get_if<Perspective>(&camera.projection);
  if (!perspective) return {};
  Json json = {{"name", camera.name.empty() ? std::string("view") : camera.name},
               {"type", "perspective"},
               {"position", array_of(view.position)},
               {"target", array_of(view.target)},
               {"up", array_of(view.up)},
               {"focal_length_mm", perspective->focal_length_mm},
               {"sensor_width_mm", perspective->sensor_width_mm},
               {"sensor_height_mm", perspective->sensor_height_mm},
               {"sensor_fit", perspective->sensor_fit == SensorFit::horizontal ? "horizontal"
                              : perspective->sensor_fit == SensorFit::vertical ? "vertical"
                                                                               : "auto"},
               {"near", camera.near_m},
               {"exposure_compensation_ev", camera.exposure.compensation_ev}};
  if (std::isfinite(camera.far_m)) json["far"] = camera.far_m;
  if (camera.lens.depth_of_field) {
    json["f_number"] = camera.f_number();
    json["focus_distance"] = camera.lens.focus_distance_m;
  }
  return json.dump(2);
}

}  // namespace obscura::app

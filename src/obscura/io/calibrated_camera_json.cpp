#include "obscura/io/calibrated_camera_json.h"

#include <cmath>

#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

double required(JsonReader& json, const std::string& key, double min, double max) {
  if (!json.has(key)) json.fail(key, "missing (a number in pixels)");
  return json.number_in(key, 0, min, max);
}

Intrinsics intrinsics_from_json(JsonReader& json, int& width, int& height) {
  Intrinsics k;
  k.fx = required(json, "fx", 1e-9, 1e9);
  k.fy = required(json, "fy", 1e-9, 1e9);
  k.cx = required(json, "cx", -1e9, 1e9);
  k.cy = required(json, "cy", -1e9, 1e9);
  k.skew = json.number_in("skew", 0, -1e9, 1e9);
  if (json.has("width") != json.has("height"))
    json.fail(json.has("width") ? "height" : "width",
              "give both width and height (the image K is given for) or neither (the film's)");
  width = json.integer("width", 0, 1, 65536);
  height = json.integer("height", 0, 1, 65536);
  json.finish();
  return k;
}

LensModel lens_from_json(JsonReader& json) {
  std::string model = json.string("model");
  std::vector<double> coefficients;
  if (json.has("coefficients")) {
    const nlohmann::ordered_json& list = json.at("coefficients");
    if (!list.is_array() || list.size() > 14)
      json.fail("coefficients", "expected an array of at most 14 numbers");
    for (const auto& v : list) {
      if (!v.is_number() || !std::isfinite(v.get<double>()))
        json.fail("coefficients", "expected finite numbers");
      coefficients.push_back(v.get<double>());
    }
  }
  json.finish();
  try {
    return lens_model_from_coefficients(model, coefficients);
  } catch (const Error& e) {
    json.fail(json.has("coefficients") ? "coefficients" : "model", e.what());
  }
}

}  // namespace

CalibratedProjection calibrated_projection_from_json(JsonReader& camera) {
  CalibratedProjection p;
  if (!camera.has("intrinsics"))
    camera.fail("intrinsics", "a calibrated camera needs {\"fx\", \"fy\", \"cx\", \"cy\"}");
  JsonReader intrinsics = camera.object("intrinsics");
  p.k = intrinsics_from_json(intrinsics, p.width_px, p.height_px);
  if (camera.has("lens")) {
    JsonReader lens = camera.object("lens");
    p.lens = lens_from_json(lens);
  }
  if (camera.has("max_field_angle_degrees"))  // absent: the lens model's own limit
    p.max_field_angle_degrees = camera.number_in("max_field_angle_degrees", 0, 1e-6, 180);
  return p;
}

}  // namespace obscura

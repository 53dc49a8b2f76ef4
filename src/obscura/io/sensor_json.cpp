#include "obscura/io/sensor_json.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "obscura/math/error.h"

namespace obscura {

SensorSpec sensor_from_json(JsonReader json) {
  SensorSpec spec;
  for (const std::string& key : json.keys()) {
    try {
      if (key == "cfa")
        spec.cfa = parse_cfa_pattern(json.string(key));
      else
        set_sensor_number(spec, key, json.number(key));
    } catch (const Error& e) {
      // RequestError names "sensor.KEY"; the scene's reader names the file and JSON path.
      const std::string message = e.what();
      const size_t colon = message.find(": ");
      json.fail(key, colon == std::string::npos ? message : message.substr(colon + 2));
    }
  }
  try {
    spec.validate();
  } catch (const Error& e) {
    const std::string field = e.where().substr(e.where().find('.') + 1);
    const std::string message = e.what();
    json.fail(field, message.substr(message.find(": ") + 2));
  }
  json.finish();
  return spec;
}

std::optional<SensorSpec> scene_camera_sensor(const std::string& scene_path,
                                              const std::string& camera_name) {
  std::string ext = std::filesystem::path(scene_path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".json" || !std::filesystem::is_regular_file(scene_path)) return std::nullopt;
  const nlohmann::ordered_json document = parse_json_file(scene_path);
  const auto cameras = document.find("cameras");
  if (cameras == document.end() || !cameras->is_array()) return std::nullopt;
  for (size_t i = 0; i < cameras->size(); ++i) {
    const nlohmann::ordered_json& camera = (*cameras)[i];
    if (!camera.is_object() || !camera.contains("sensor")) continue;
    const auto name = camera.find("name");  // camera_from_json's default name is "camera"
    const std::string named = name != camera.end() && name->is_string() ? name->get<std::string>()
                                                                        : std::string("camera");
    if (named != camera_name) continue;
    JsonReader reader(camera, scene_path, "$.cameras[" + std::to_string(i) + "]");
    return sensor_from_json(reader.object("sensor"));
  }
  return std::nullopt;
}

}  // namespace obscura

// The JSON camera's "sensor" block (docs/sensor.md): the raw sensor a camera carries, its fields
// named as set_sensor_field names them, e.g.
//   "sensor": {"cfa": "RGGB", "pixel_pitch_um": 3.76, "full_well_e": 51000, "read_noise_e": 1.6}
// camera_from_json checks the block when the scene is read (an error names its JSON path); the
// command line and Python read it back by the camera's name with scene_camera_sensor.
#pragma once

#include <optional>
#include <string>

#include "obscura/io/json_reader.h"
#include "obscura/sensor/sensor_spec.h"

namespace obscura {

// The block's sensor over the defaults, validated. Throws obscura::Error naming the key.
SensorSpec sensor_from_json(JsonReader json);

// The sensor of the camera named `camera_name` in the JSON scene file `scene_path` (nothing when
// that camera has no "sensor" block, or the file is not a JSON scene).
std::optional<SensorSpec> scene_camera_sensor(const std::string& scene_path,
                                              const std::string& camera_name);

}  // namespace obscura

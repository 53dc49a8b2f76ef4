// The calibrated camera of the JSON scene file (docs/scene-format.md, "Cameras"): "intrinsics"
// {"fx", "fy", "cx", "cy", "skew", "width", "height"} in OpenCV pixels, "lens" {"model",
// "coefficients"} and "max_field_angle_degrees", checked as strictly as every other key.
#pragma once

#include "obscura/camera/calibrated_projection.h"
#include "obscura/io/json_reader.h"

namespace obscura {

// Reads the calibrated keys of a camera object (the caller reads the rest and calls finish()).
CalibratedProjection calibrated_projection_from_json(JsonReader& camera);

}  // namespace obscura

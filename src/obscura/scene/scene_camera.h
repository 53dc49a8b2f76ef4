// A named camera of a scene file. `camera` is what the renderers use; the remaining fields keep
// the file's own description (glTF / JSON values) for what Camera does not model yet.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/scene/instance.h"

namespace obscura {

enum class CameraProjection { kPerspective, kOrthographic };

struct SceneCamera {
  std::string name;
  Camera camera;
  CameraProjection projection = CameraProjection::kPerspective;
  double aspect_ratio = 0;  // width / height the file asks for; 0 = from the film resolution
  double z_near = 0.01, z_far = std::numeric_limits<double>::infinity();  // metres
  double x_mag = 0, y_mag = 0;  // orthographic: half the view's width and height, metres
  // Thin lens (f_number 0 = pinhole) and shutter, as the file gives them.
  double focal_length_mm = 0;  // 0 when the file gives a field of view instead
  double sensor_width_mm = 36, sensor_height_mm = 24;
  double f_number = 0;
  double focus_distance = 0;                   // metres; 0 = unset
  int aperture_blades = 0;                     // 0 = a circular aperture
  double shutter_open = 0, shutter_close = 0;  // seconds
  // Keyframed camera→world transforms for motion blur (empty: static), as Instance::motion.
  std::vector<TransformKey> motion;
};

}  // namespace obscura

// The one place where cameras from files (glTF, the JSON scene file) become Obscura cameras.
// Kept small and separate so that it follows the camera model as that grows.
#pragma once

#include <string>

#include "obscura/io/json_reader.h"
#include "obscura/math/bounds.h"
#include "obscura/scene/scene.h"
#include "obscura/scene/scene_camera.h"

namespace obscura {

// glTF perspective camera: vertical field of view in radians; aspect 0 = from the film.
SceneCamera perspective_camera(std::string name, const Transform& world_from_camera,
                               double yfov_radians, double aspect_ratio, double z_near,
                               double z_far);
// glTF orthographic camera: half-width and half-height of the view in metres.
SceneCamera orthographic_camera(std::string name, const Transform& world_from_camera, double x_mag,
                                double y_mag, double z_near, double z_far);

// A camera object of the JSON scene file (see docs/scene-format.md, "cameras").
SceneCamera camera_from_json(JsonReader& json);

// A camera that sees all of `bounds` from the front (+Z side), for files without a camera.
SceneCamera framing_camera(const Bounds3f& bounds);

// Makes the camera named `name` (the first one when empty) the scene's render camera, adding a
// framing camera first when the scene has none. Throws naming `where` for an unknown name.
void finish_cameras(Scene& scene, const std::string& name, const std::string& where);

}  // namespace obscura

// The one place where cameras from files (glTF, the JSON scene file) become Obscura cameras.
// glTF's values go through io/gltf_camera.h; the JSON keys are listed in
// docs/scene-format.md ("Cameras").
#pragma once

#include <string>

#include "obscura/camera/camera.h"
#include "obscura/io/gltf_camera.h"
#include "obscura/io/json_reader.h"
#include "obscura/math/bounds.h"
#include "obscura/scene/scene.h"

namespace obscura {

// A glTF camera at its node's transform (scale removed). `where` names it in errors.
Camera gltf_perspective_camera(std::string name, const Transform& world_from_camera,
                               const GltfPerspective& perspective, const std::string& where);
Camera gltf_orthographic_camera(std::string name, const Transform& world_from_camera,
                                const GltfOrthographic& orthographic, const std::string& where);

// A camera object of the JSON scene file.
Camera camera_from_json(JsonReader& json);

// A camera that sees all of `bounds` from a three-quarter view (front, +Z, right, +X, and above,
// +Y), for files without a camera.
Camera framing_camera(const Bounds3f& bounds);

// Makes the camera named `name` (the first one when empty) the scene's render camera, adding a
// framing camera first when the scene has none. Throws naming `where` for an unknown name.
void finish_cameras(Scene& scene, const std::string& name, const std::string& where);

}  // namespace obscura

// Frames: where the camera sits in the world, and how a scene's up axis becomes Obscura's.
//
// Obscura's world is right-handed and Y-up (as glTF); the camera looks down its −Z axis with +X
// right and +Y up. Z-up scenes (Blender, CAD) are converted when loaded, by an explicit setting.
#pragma once

#include <string_view>

#include "obscura/math/transform.h"
#include "obscura/math/vector.h"

namespace obscura {

enum class UpAxis { y, z };

// The rotation taking a scene authored with `up` into Obscura's Y-up world. For Z-up it maps
// (x, y, z) to (x, z, −y): +Z becomes +Y and +Y (Blender's "forward") becomes −Z, exactly as
// Blender's glTF exporter does with "+Y up".
Transform y_up_from(UpAxis up);
// "y" or "z" (case-insensitive); throws obscura::Error naming the value otherwise.
UpAxis parse_up_axis(std::string_view text);

// The world_from_camera transform of a camera at `eye` looking at `target`, with its +Y as close
// to `up` as possible. Preconditions: eye ≠ target, up not parallel to target − eye.
Transform world_from_camera_look_at(Point3d eye, Point3d target, Vector3d up = {0, 1, 0});

}  // namespace obscura

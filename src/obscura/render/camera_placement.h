// Placing a camera by its position, the point it looks at and its up direction (the command
// line's --position, --look-at, --up; Python's position=, look_at=, up=; the dataset views of
// render/dataset_views.h). The pose becomes a fixed one: a camera placed so does not move over
// the shutter.
#pragma once

#include <optional>

#include "obscura/camera/camera.h"

namespace obscura {

struct CameraPlacement {
  std::optional<Point3d> position = std::nullopt;  // where the camera's centre is (m)
  std::optional<Point3d> look_at = std::nullopt;   // the point the optical axis passes through
  std::optional<Vector3d> up = std::nullopt;       // the direction the image's up is turned towards
  bool empty() const { return !position && !look_at && !up; }
};

// The pose `placement` asks for, starting from `world_from_camera` (the camera's pose at the
// shutter's opening): a position alone moves the camera and keeps its orientation; a look-at
// point turns it to look there, its up as close to `up` as the view allows (default: world +Y,
// or the camera's own up when it looks straight up or down); an up alone rolls the camera about
// its view direction. Throws RequestError naming the option for a look-at point at the camera's
// position, an up of zero length or along the view direction, a non-finite value.
Transform placed_pose(const Transform& world_from_camera, const CameraPlacement& placement);

// Parses "X,Y,Z" (finite numbers) for `option` ("--position"); throws RequestError.
Vector3d parse_placement_vector(const std::string& text, const std::string& option);

// A camera at `eye` looking at `target` with its up towards `up`, errors as placed_pose's; the
// options named in messages are `where`'s ("--position", "view 3").
Transform look_at_pose(Point3d eye, Point3d target, Vector3d up, const std::string& where);

}  // namespace obscura

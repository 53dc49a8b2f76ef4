#include "obscura/camera/frames.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

Transform y_up_from(UpAxis up) {
  if (up == UpAxis::y) return {};
  Matrix4 m = Matrix4::from_rows({{{1, 0, 0, 0}, {0, 0, 1, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}}});
  return {m, transpose(m)};  // a rotation: its inverse is its transpose
}

UpAxis parse_up_axis(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (lower == "y") return UpAxis::y;
  if (lower == "z") return UpAxis::z;
  throw Error("up axis", "expected 'y' or 'z'; got '" + std::string(text) + "'");
}

Transform world_from_camera_look_at(Point3d eye, Point3d target, Vector3d up) {
  return inverse(Transform::look_at(eye, target, up));
}

}  // namespace obscura

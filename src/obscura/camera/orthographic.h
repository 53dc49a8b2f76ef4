// The orthographic projection: parallel rays perpendicular to the film. The film covers a
// rectangle of the world `view_width_m` × `view_height_m` wide (glTF's 2·xmag × 2·ymag; Blender's
// ortho_scale is the larger of the two); an object's size on film does not depend on its depth.
#pragma once

#include <optional>

namespace obscura {

struct Orthographic {
  double view_height_m = 2;  // > 0
  // > 0 when given; otherwise view_height_m × the image's physical aspect ratio (square pixels
  // stay square). glTF's xmag/ymag give both, and a film of another aspect is then stretched,
  // as glTF's projection matrix does.
  std::optional<double> view_width_m;
};

// Throws obscura::Error naming the first invalid parameter and its value.
void validate(const Orthographic& o);

}  // namespace obscura

// The rasterizer's view of the thin lens: for one lens point and one shutter time, the view and
// projection matrices that image the scene exactly as the camera's rays through that lens point
// do (Camera::generate_ray with the same lens sample and time). Averaging renders over many lens
// points and times gives depth of field and motion blur by accumulation.
//
// The tracer's ray for window point (x_w, y_w) (camera space, on z = −1) leaves the lens point
// L = (L_x, L_y, 0) towards Q = (x_w, y_w, −1)·S_f on the focus plane. A camera-space point P at
// depth d = −P_z lies on that ray when Q = L + (P − L)·S_f/d, that is
//   x_w = (P_x − L_x)/d + L_x/S_f,   y_w = (P_y − L_y)/d + L_y/S_f.
// So: move the eye to L (view = translate(−L) · camera_from_world(t)) and shift the screen
// window by −L/S_f (an off-axis glFrustum). Depth is unchanged (L lies on the lens plane z = 0),
// so the near and far planes clip the same points as the tracer's rays, and points on the focus
// plane (d = S_f) land on the same pixel for every lens point.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/math/matrix4.h"
#include "obscura/math/vector.h"

namespace obscura {

struct LensView {
  Matrix4 view;          // camera_from_world with the eye moved to the lens point (at time_s)
  Matrix4 projection;    // clip_from_camera, OpenGL conventions, sheared for the lens point
  Point3d eye_world;     // the lens point in world space (the eye for specular shading)
  Point2d lens_point_m;  // the lens point on the lens plane, camera x/y, metres
};

// The matrices for lens sample `lens_sample` ∈ [0,1)² (warped onto the aperture's shape as
// generate_ray does; (½, ½) is the lens centre) at time `time_s`. Without depth of field every
// lens sample gives the pinhole's matrices, view_matrix(time_s) and projection_matrix().
// Throws obscura::Error for a camera without a projection matrix (spherical projections).
LensView lens_view(const Camera& camera, Point2d lens_sample, double time_s = 0);

}  // namespace obscura

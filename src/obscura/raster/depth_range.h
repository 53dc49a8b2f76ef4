// The depth range a frame is rasterized with.
#pragma once

#include "obscura/math/bounds.h"
#include "obscura/math/matrix4.h"

namespace obscura::raster {

// A perspective projection with its near and far planes moved in to the scene's bounds (seen
// from `camera_from_world`), where they lie outside them. Window depth is stored as a float,
// and with depth ∝ 1 − n/z its resolution at distance z is about z²·2⁻²⁴/n: a glTF camera's near
// plane of 0.06 mm (TransmissionTest) leaves surfaces 1.6 mm apart at 1.5 m fighting over each
// pixel. Nothing lies between the camera's planes and the bounds, so clipping at the bounds
// changes no pixel; only depth precision improves.
//
// An orthographic projection whose far plane is at infinity (glOrtho's limit: every depth at the
// near plane, a singular matrix) gets a finite far plane just beyond the bounds, its near plane
// `orthographic_near_m` kept; nothing lies beyond the bounds, so no pixel changes. Other
// projections are returned as they are.
Matrix4 fit_depth_range(const Matrix4& projection, const Matrix4& camera_from_world,
                        const Bounds3f& bounds, double orthographic_near_m = 0);

}  // namespace obscura::raster

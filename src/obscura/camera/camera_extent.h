// The camera's side of the value contract (math/value_limits.h): where its rays start and how far
// they spread must be something single-precision ray tracing can represent. Calibration poses,
// scene-file positions, lens shifts and command-line optics all reach Camera::validate, which
// calls this.
#pragma once

namespace obscura {

struct Camera;

// Throws obscura::Error naming the field (camera.position, camera.focal_length_mm, ...) when a
// ray origin would lie beyond ±kMaxWorldCoordinateM, or a ray direction's slope beyond
// kMaxRaySlope, from a camera whose parameters are each otherwise valid.
void validate_world_extent(const Camera& camera);

// The largest tangent of the angle between a primary ray and the view axis: a field of view of
// 2·atan(1e6), 179.9999°. Wider windows come only from degenerate optics (a focal length of
// 1e-20 mm, a sensor of 1e300 mm, a lens shift of 1e20) whose rays overflow what a float holds.
inline constexpr double kMaxRaySlope = 1e6;

}  // namespace obscura

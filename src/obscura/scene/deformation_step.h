// Where a time falls among a MeshDeformation's evenly spaced time steps: what posing a mesh
// (Mesh::posed_at) and the tracer's deformed normals both interpolate between.
#pragma once

#include <algorithm>
#include <cstddef>

#include "obscura/scene/mesh.h"

namespace obscura {

struct DeformationStep {
  size_t index = 0;    // the step at or before the time
  float fraction = 0;  // towards step index + 1, in [0, 1]
};

// For a deformation of `steps` ≥ 2 time steps; times outside [open_s, close_s] are clamped.
inline DeformationStep deformation_step(const MeshDeformation& d, size_t steps, double time_s) {
  const size_t segments = steps - 1;
  const double span = d.close_s - d.open_s;
  double u = span > 0 ? (time_s - d.open_s) / span * double(segments) : 0;
  u = std::clamp(u, 0.0, double(segments));
  const size_t i = std::min(size_t(u), segments - 1);
  return {i, float(u - double(i))};
}

}  // namespace obscura

// A transform that moves over time: keyframes (time, transform), interpolated between keys and
// held constant before the first and after the last. Used for the camera's world_from_camera,
// sampled over the shutter interval for motion blur.
//
// Each key is decomposed into translation, rotation and per-axis scale (M = T·R·S);
// translation and scale interpolate linearly and rotation by quaternion slerp along the shorter
// arc, so a spinning camera turns at a constant rate instead of shrinking mid-way as a
// matrix lerp would. A key with shear (a node hierarchy's non-uniform scale under a rotation,
// or an exporter's float noise) is taken apart by the polar decomposition M = T · R · S, S the
// full stretch matrix, interpolated entry by entry.
#pragma once

#include <vector>

#include "obscura/math/transform.h"

namespace obscura {

class AnimatedTransform {
 public:
  // A transform that does not move. Implicit on purpose: `camera.world_from_camera = t;`.
  AnimatedTransform(const Transform& fixed = {}) : keys_{{0.0, fixed}} {}

  struct Key {
    double time_s;
    Transform transform;
  };
  // Precondition: at least one key, times strictly increasing, finite; every key affine and
  // invertible. Throws obscura::Error naming the key otherwise.
  explicit AnimatedTransform(std::vector<Key> keys);

  Transform at(double time_s) const;
  bool is_animated() const { return keys_.size() > 1; }
  const std::vector<Key>& keys() const { return keys_; }

 private:
  // A key taken apart once, at construction: M = T · R(q) · S.
  struct Parts {
    Vector3d translation;
    double rotation[4];  // unit quaternion (w, x, y, z)
    Vector3d scale;
    bool sheared;          // the key has shear: `stretch` is its full stretch matrix
    double stretch[3][3];  // S, row-major (diag(scale) for a key without shear)
  };
  std::vector<Key> keys_;
  std::vector<Parts> parts_;  // one per key when animated
};

}  // namespace obscura

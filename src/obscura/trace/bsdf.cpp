#include "obscura/trace/bsdf.h"

namespace obscura {

bool refract(Vector3f wi, Vector3f n, float eta, Vector3f* wt, float* eta_relative) {
  float cos_i = dot(n, wi);
  if (cos_i < 0) {  // leaving the inside: the ratio inverts and the normal flips
    eta = 1 / eta;
    cos_i = -cos_i;
    n = -n;
  }
  float sin2_t = std::max(0.f, 1 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1) return false;
  float cos_t = std::sqrt(1 - sin2_t);
  *wt = -wi / eta + n * (cos_i / eta - cos_t);
  *eta_relative = eta;
  return true;
}

}  // namespace obscura

// Axis-aligned bounding boxes. An empty box has min > max, so that the union with any point is
// that point.
#pragma once

#include <limits>

#include "obscura/math/vector.h"

namespace obscura {

template <typename T>
struct Bounds3 {
  Point3<T> min{std::numeric_limits<T>::max(), std::numeric_limits<T>::max(),
                std::numeric_limits<T>::max()};
  Point3<T> max{std::numeric_limits<T>::lowest(), std::numeric_limits<T>::lowest(),
                std::numeric_limits<T>::lowest()};

  constexpr Bounds3() = default;
  constexpr explicit Bounds3(Point3<T> p) : min(p), max(p) {}
  constexpr Bounds3(Point3<T> a, Point3<T> b) : min(obscura::min(a, b)), max(obscura::max(a, b)) {}

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  Vector3<T> diagonal() const { return max - min; }
  Point3<T> center() const { return min + diagonal() / T(2); }
  bool contains(Point3<T> p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
           p.z <= max.z;
  }
  // Index of the longest axis (0 = x, 1 = y, 2 = z).
  int max_extent() const {
    Vector3<T> d = diagonal();
    return d.x > d.y && d.x > d.z ? 0 : (d.y > d.z ? 1 : 2);
  }
  T surface_area() const {
    if (empty()) return T(0);
    Vector3<T> d = diagonal();
    return T(2) * (d.x * d.y + d.x * d.z + d.y * d.z);
  }
};

template <typename T>
Bounds3<T> unite(const Bounds3<T>& b, Point3<T> p) {
  Bounds3<T> r;
  r.min = min(b.min, p);
  r.max = max(b.max, p);
  return r;
}

template <typename T>
Bounds3<T> unite(const Bounds3<T>& a, const Bounds3<T>& b) {
  Bounds3<T> r;
  r.min = min(a.min, b.min);
  r.max = max(a.max, b.max);
  return r;
}

using Bounds3f = Bounds3<float>;
using Bounds3d = Bounds3<double>;

// A rectangle of pixels [min, max) on the film.
struct Bounds2i {
  Point2i min, max;
  int width() const { return max.x - min.x; }
  int height() const { return max.y - min.y; }
  long long area() const { return (long long)width() * height(); }
  bool empty() const { return max.x <= min.x || max.y <= min.y; }
};

}  // namespace obscura

// Vectors, points and normals in 2D and 3D.
//
// Points, vectors and normals are distinct types because a transform treats them differently:
// points translate, vectors do not, normals transform by the inverse transpose. Arithmetic is
// defined only where it means something (point − point = vector, point + vector = point).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace obscura {

template <typename T>
struct Vector2 {
  T x{}, y{};
  constexpr Vector2() = default;
  constexpr Vector2(T x_, T y_) : x(x_), y(y_) {}
  constexpr T operator[](int i) const { return i == 0 ? x : y; }
  constexpr T& operator[](int i) { return i == 0 ? x : y; }
  constexpr Vector2 operator+(Vector2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vector2 operator-(Vector2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vector2 operator*(T s) const { return {x * s, y * s}; }
  constexpr Vector2 operator/(T s) const { return {x / s, y / s}; }
  constexpr Vector2 operator-() const { return {-x, -y}; }
  constexpr bool operator==(const Vector2&) const = default;
};

template <typename T>
struct Point2 {
  T x{}, y{};
  constexpr Point2() = default;
  constexpr Point2(T x_, T y_) : x(x_), y(y_) {}
  constexpr T operator[](int i) const { return i == 0 ? x : y; }
  constexpr T& operator[](int i) { return i == 0 ? x : y; }
  constexpr Point2 operator+(Vector2<T> v) const { return {x + v.x, y + v.y}; }
  constexpr Point2 operator-(Vector2<T> v) const { return {x - v.x, y - v.y}; }
  constexpr Vector2<T> operator-(Point2 p) const { return {x - p.x, y - p.y}; }
  constexpr bool operator==(const Point2&) const = default;
};

template <typename T>
struct Vector3 {
  T x{}, y{}, z{};
  constexpr Vector3() = default;
  constexpr Vector3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Vector3(const Vector3<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}
  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vector3 operator+(Vector3 o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vector3 operator-(Vector3 o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vector3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vector3 operator/(T s) const { return {x / s, y / s, z / s}; }
  constexpr Vector3 operator-() const { return {-x, -y, -z}; }
  constexpr Vector3& operator+=(Vector3 o) { return *this = *this + o; }
  constexpr Vector3& operator-=(Vector3 o) { return *this = *this - o; }
  constexpr Vector3& operator*=(T s) { return *this = *this * s; }
  constexpr bool operator==(const Vector3&) const = default;
};

template <typename T>
struct Point3 {
  T x{}, y{}, z{};
  constexpr Point3() = default;
  constexpr Point3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Point3(const Point3<U>& p) : x(T(p.x)), y(T(p.y)), z(T(p.z)) {}
  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Point3 operator+(Vector3<T> v) const { return {x + v.x, y + v.y, z + v.z}; }
  constexpr Point3 operator-(Vector3<T> v) const { return {x - v.x, y - v.y, z - v.z}; }
  constexpr Vector3<T> operator-(Point3 p) const { return {x - p.x, y - p.y, z - p.z}; }
  constexpr Point3& operator+=(Vector3<T> v) { return *this = *this + v; }
  constexpr bool operator==(const Point3&) const = default;
};

template <typename T>
struct Normal3 {
  T x{}, y{}, z{};
  constexpr Normal3() = default;
  constexpr Normal3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  constexpr explicit Normal3(Vector3<T> v) : x(v.x), y(v.y), z(v.z) {}
  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Normal3 operator-() const { return {-x, -y, -z}; }
  constexpr Normal3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr bool operator==(const Normal3&) const = default;
};

template <typename T>
struct Vector4 {
  T x{}, y{}, z{}, w{};
  constexpr Vector4() = default;
  constexpr Vector4(T x_, T y_, T z_, T w_) : x(x_), y(y_), z(z_), w(w_) {}
  constexpr T operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  constexpr T& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  constexpr Vector4 operator+(Vector4 o) const { return {x + o.x, y + o.y, z + o.z, w + o.w}; }
  constexpr Vector4 operator-(Vector4 o) const { return {x - o.x, y - o.y, z - o.z, w - o.w}; }
  constexpr Vector4 operator*(T s) const { return {x * s, y * s, z * s, w * s}; }
  constexpr bool operator==(const Vector4&) const = default;
};

using Vector2f = Vector2<float>;
using Vector2d = Vector2<double>;
using Vector2i = Vector2<int>;
using Point2f = Point2<float>;
using Point2d = Point2<double>;
using Point2i = Point2<int>;
using Vector3f = Vector3<float>;
using Vector3d = Vector3<double>;
using Point3f = Point3<float>;
using Point3d = Point3<double>;
using Normal3f = Normal3<float>;
using Normal3d = Normal3<double>;
using Vector4f = Vector4<float>;
using Vector4d = Vector4<double>;

template <typename T>
constexpr Vector3<T> operator*(T s, Vector3<T> v) { return v * s; }
template <typename T>
constexpr Vector2<T> operator*(T s, Vector2<T> v) { return v * s; }

template <typename T>
constexpr T dot(Vector3<T> a, Vector3<T> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename T>
constexpr T dot(Normal3<T> n, Vector3<T> v) { return n.x * v.x + n.y * v.y + n.z * v.z; }
template <typename T>
constexpr T dot(Vector3<T> v, Normal3<T> n) { return dot(n, v); }
template <typename T>
constexpr T dot(Vector2<T> a, Vector2<T> b) { return a.x * b.x + a.y * b.y; }
template <typename T>
constexpr T abs_dot(Vector3<T> a, Vector3<T> b) { return std::abs(dot(a, b)); }
template <typename T>
constexpr T abs_dot(Normal3<T> n, Vector3<T> v) { return std::abs(dot(n, v)); }

template <typename T>
constexpr Vector3<T> cross(Vector3<T> a, Vector3<T> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <typename T>
T length_squared(Vector3<T> v) { return dot(v, v); }
template <typename T>
T length(Vector3<T> v) { return std::sqrt(dot(v, v)); }
template <typename T>
T length(Vector2<T> v) { return std::sqrt(dot(v, v)); }
template <typename T>
Vector3<T> normalize(Vector3<T> v) { return v / length(v); }
template <typename T>
Normal3<T> normalize(Normal3<T> n) {
  return Normal3<T>(normalize(Vector3<T>(n.x, n.y, n.z)));
}
template <typename T>
T distance(Point3<T> a, Point3<T> b) { return length(a - b); }
template <typename T>
T distance_squared(Point3<T> a, Point3<T> b) { return length_squared(a - b); }

template <typename T>
constexpr Vector3<T> to_vector(Normal3<T> n) { return {n.x, n.y, n.z}; }
template <typename T>
constexpr Vector3<T> to_vector(Point3<T> p) { return {p.x, p.y, p.z}; }

// Flips n to lie in the hemisphere of v.
template <typename T>
Normal3<T> face_forward(Normal3<T> n, Vector3<T> v) { return dot(n, v) < T(0) ? -n : n; }

template <typename T>
Point3<T> lerp(T t, Point3<T> a, Point3<T> b) { return a + (b - a) * t; }

template <typename T>
Point3<T> min(Point3<T> a, Point3<T> b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <typename T>
Point3<T> max(Point3<T> a, Point3<T> b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

// Builds two unit vectors that complete v (unit length) to a right-handed orthonormal basis
// without branches on the sign of v.z (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
template <typename T>
void coordinate_system(Vector3<T> v, Vector3<T>* s, Vector3<T>* t) {
  T sign = std::copysign(T(1), v.z);
  T a = T(-1) / (sign + v.z);
  T b = v.x * v.y * a;
  *s = Vector3<T>(T(1) + sign * v.x * v.x * a, sign * b, -sign * v.x);
  *t = Vector3<T>(b, sign + v.y * v.y * a, -v.y);
}

}  // namespace obscura

#include "obscura/math/vector.h"

#include <gtest/gtest.h>

#include "obscura/math/bounds.h"
#include "obscura/math/rng.h"

namespace obscura {
namespace {

TEST(Vector, CrossProductOfAxesIsRightHanded) {
  EXPECT_EQ(cross(Vector3f(1, 0, 0), Vector3f(0, 1, 0)), Vector3f(0, 0, 1));
  EXPECT_EQ(cross(Vector3f(0, 1, 0), Vector3f(0, 0, 1)), Vector3f(1, 0, 0));
  EXPECT_EQ(cross(Vector3f(0, 0, 1), Vector3f(1, 0, 0)), Vector3f(0, 1, 0));
}

TEST(Vector, PointAndVectorArithmetic) {
  Point3f p(1, 2, 3), q(4, 6, 3);
  EXPECT_EQ(q - p, Vector3f(3, 4, 0));
  EXPECT_FLOAT_EQ(distance(p, q), 5.f);  // a 3-4-5 triangle
  EXPECT_EQ(p + (q - p), q);
  EXPECT_FLOAT_EQ(length(normalize(Vector3f(3, 4, 12))), 1.f);
  EXPECT_EQ(face_forward(Normal3f(0, 0, 1), Vector3f(0, 0, -1)), Normal3f(0, 0, -1));
}

TEST(Vector, CoordinateSystemIsOrthonormalAndRightHanded) {
  Pcg32 rng(5);
  for (int i = 0; i < 1000; ++i) {
    Vector3f v = normalize(Vector3f(rng.next_float() * 2 - 1, rng.next_float() * 2 - 1,
                                    rng.next_float() * 2 - 1));
    Vector3f s, t;
    coordinate_system(v, &s, &t);
    EXPECT_NEAR(length(s), 1, 1e-5);
    EXPECT_NEAR(length(t), 1, 1e-5);
    EXPECT_NEAR(dot(s, v), 0, 1e-5);
    EXPECT_NEAR(dot(t, v), 0, 1e-5);
    EXPECT_NEAR(dot(s, t), 0, 1e-5);
    Vector3f c = cross(s, t);  // s × t = v for a right-handed (s, t, v)
    EXPECT_NEAR(c.x, v.x, 1e-5);
    EXPECT_NEAR(c.y, v.y, 1e-5);
    EXPECT_NEAR(c.z, v.z, 1e-5);
  }
}

TEST(Bounds, UnionAndMeasures) {
  Bounds3f b;
  EXPECT_TRUE(b.empty());
  b = unite(b, Point3f(1, 2, 3));
  b = unite(b, Point3f(-1, 0, 5));
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.min, Point3f(-1, 0, 3));
  EXPECT_EQ(b.max, Point3f(1, 2, 5));
  EXPECT_FLOAT_EQ(b.surface_area(), 2 * (2 * 2 + 2 * 2 + 2 * 2));
  EXPECT_TRUE(b.contains(Point3f(0, 1, 4)));
  EXPECT_FALSE(b.contains(Point3f(0, 3, 4)));
  EXPECT_EQ(Bounds3f(Point3f(0, 0, 0), Point3f(1, 5, 2)).max_extent(), 1);
}

}  // namespace
}  // namespace obscura

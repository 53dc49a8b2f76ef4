// Mesh::deformation: vertices at evenly spaced times, interpolated linearly and held outside,
// and the checks Scene::validate makes of them.
#include <gtest/gtest.h>

#include "obscura/math/error.h"
#include "obscura/scene/scene.h"

namespace obscura {
namespace {

// One triangle sliding 3 m along +X over [1 s, 2 s] in three steps (0, 1, 3 m: not uniform in
// speed, so that the segments are told apart); its normal turns from +Z to +X halfway.
Mesh sliding_triangle() {
  Mesh m;
  m.name = "slider";
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.indices = {0, 1, 2};
  m.deformation.open_s = 1;
  m.deformation.close_s = 2;
  for (float dx : {0.f, 1.f, 3.f}) {
    std::vector<Point3f> p = m.positions;
    for (Point3f& v : p) v.x += dx;
    m.deformation.positions.push_back(p);
  }
  m.deformation.normals = {m.normals, m.normals, {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}};
  return m;
}

TEST(MeshDeformation, PosedAtInterpolatesBetweenStepsAndHoldsOutside) {
  Mesh m = sliding_triangle();
  ASSERT_TRUE(m.deforms());
  // (time, x offset): steps at 1, 1.5, 2 s; 1.25 s is halfway through the first segment (0.5 m),
  // 1.75 s halfway through the second (1 + 1 = 2 m).
  for (auto [t, dx] : {std::pair{0.0, 0.0},
                       {1.0, 0.0},
                       {1.25, 0.5},
                       {1.5, 1.0},
                       {1.75, 2.0},
                       {2.0, 3.0},
                       {9.0, 3.0}}) {
    Mesh posed = m.posed_at(t);
    EXPECT_FALSE(posed.deforms());
    EXPECT_FLOAT_EQ(posed.positions[1].x, 1 + float(dx)) << t;
    EXPECT_FLOAT_EQ(posed.positions[2].y, 1) << t;
  }
  // Halfway between +Z and +X: the unit normal at 45°.
  Normal3f n = m.posed_at(1.75).normals[0];
  EXPECT_NEAR(n.x, std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(n.z, std::sqrt(0.5), 1e-6);
}

TEST(MeshDeformation, ARigidMeshPosesAsItself) {
  Mesh m = sliding_triangle();
  m.deformation = {};
  EXPECT_FALSE(m.deforms());
  EXPECT_EQ(m.posed_at(5).positions, m.positions);
}

TEST(MeshDeformation, ValidateNamesABadStep) {
  Scene scene;
  scene.materials.resize(1);
  scene.add_mesh(sliding_triangle());
  EXPECT_NO_THROW(scene.validate());
  scene.meshes[0].deformation.positions[1].pop_back();
  try {
    scene.validate();
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("deformation step 1 has 2 positions for 3 vertices"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace obscura

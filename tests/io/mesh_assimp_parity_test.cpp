// Obscura's OBJ and PLY loaders against the Assimp loader they replaced, on the test meshes:
// scenes, tests and renders written against the Assimp path must see the same meshes, names,
// materials, vertices and triangles. (Positions may differ in the last digit: Assimp's number
// parser rounds less exactly than std::from_chars.)
#include <gtest/gtest.h>

#include <variant>

#include "obscura/io/assimp_loader.h"
#include "obscura/io/obj_loader.h"
#include "obscura/io/ply_loader.h"
#include "test_paths.h"

namespace obscura {
namespace {

void expect_same_scene(const Scene& ours, const Scene& assimp) {
  ASSERT_EQ(ours.meshes.size(), assimp.meshes.size());
  ASSERT_EQ(ours.instances.size(), assimp.instances.size());
  ASSERT_EQ(ours.materials.size(), assimp.materials.size());
  for (size_t i = 0; i < ours.materials.size(); ++i) {
    EXPECT_EQ(ours.materials[i].name, assimp.materials[i].name);
    const auto& a = std::get<PhongMaterial>(ours.materials[i].model);
    const auto& b = std::get<PhongMaterial>(assimp.materials[i].model);
    EXPECT_EQ(a.diffuse, b.diffuse) << ours.materials[i].name;
    EXPECT_EQ(a.specular, b.specular) << ours.materials[i].name;
    EXPECT_EQ(a.shininess, b.shininess) << ours.materials[i].name;
    EXPECT_EQ(a.diffuse_texture.valid(), b.diffuse_texture.valid());
    EXPECT_EQ(ours.materials[i].emission, assimp.materials[i].emission);
  }
  for (size_t i = 0; i < ours.instances.size(); ++i) {
    EXPECT_EQ(ours.instances[i].name, assimp.instances[i].name);
    EXPECT_EQ(ours.instances[i].mesh, assimp.instances[i].mesh);
  }
  for (size_t i = 0; i < ours.meshes.size(); ++i) {
    const Mesh& a = ours.meshes[i];
    const Mesh& b = assimp.meshes[i];
    SCOPED_TRACE(a.name);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(a.normals.size(), b.normals.size());
    EXPECT_EQ(a.uvs.size(), b.uvs.size());
    EXPECT_EQ(a.colors.size(), b.colors.size());
    for (size_t v = 0; v < a.positions.size(); ++v) {
      Vector3f d = a.positions[v] - b.positions[v];
      EXPECT_LT(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}),
                1e-5f * (1 + std::abs(b.positions[v].x) + std::abs(b.positions[v].y) +
                         std::abs(b.positions[v].z)))
          << "vertex " << v;
    }
    for (size_t v = 0; v < a.uvs.size(); ++v) {
      EXPECT_NEAR(a.uvs[v].x, b.uvs[v].x, 1e-5) << "vertex " << v;
      EXPECT_NEAR(a.uvs[v].y, b.uvs[v].y, 1e-5) << "vertex " << v;
    }
  }
}

TEST(MeshAssimpParity, ObjFiles) {
  for (const std::string& path :
       {test::data_path("meshes/teapot/teapot.obj"),
        test::data_path("meshes/mori_knob/testObj.obj"),
        test::source_path("scenes/assets/cornell/cornell_box_measured.obj")}) {
    SCOPED_TRACE(path);
    expect_same_scene(load_obj(path), load_with_assimp(path));
  }
}

TEST(MeshAssimpParity, PlyFiles) {
  for (const std::string& path : {test::data_path("meshes/stanford_bunny/bun_zipper_res4.ply"),
                                  test::data_path("meshes/stanford_bunny/bun_zipper_res3.ply"),
                                  test::source_path("scenes/assets/bunny/bun_zipper_res2.ply")}) {
    SCOPED_TRACE(path);
    expect_same_scene(load_ply(path), load_with_assimp(path));
  }
}

}  // namespace
}  // namespace obscura

// The Assimp loader against the meshes in tests/data/ and scenes/assets/ (counts from the shared
// asset collection's README, which counted faces with its own parser) and the measured Cornell
// box's MTL values.
#include "obscura/io/assimp_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <variant>

#include "obscura/math/error.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

TEST(AssimpLoader, StanfordBunnyPly) {
  // scenes/assets/README.md: bun_zipper_res2.ply, 8,171 vertices, 16,301 triangles; the
  // full-resolution bunny's bounding box is about 0.156 × 0.154 × 0.121 m, and decimation keeps it.
  Scene scene = load_with_assimp(test::source_path("scenes/assets/bunny/bun_zipper_res2.ply"));
  EXPECT_EQ(scene.stats().triangles, 16301u);
  // Vertices no face uses are not kept, so there may be fewer than the file lists.
  EXPECT_LE(scene.stats().vertices, 8171u);
  EXPECT_GT(scene.stats().vertices, 8000u);
  Vector3f size = scene.bounds().diagonal();
  EXPECT_NEAR(size.x, 0.156, 0.001);
  EXPECT_NEAR(size.y, 0.154, 0.001);
  EXPECT_NEAR(size.z, 0.121, 0.001);
}

TEST(AssimpLoader, BunnyLevelsOfDetail) {
  // README: res3 3,851, res4 948 triangles (res2 above).
  for (auto [file, triangles] :
       {std::pair{"bun_zipper_res3.ply", 3851u}, std::pair{"bun_zipper_res4.ply", 948u}}) {
    Scene scene = load_with_assimp(test::data_path(std::string("meshes/stanford_bunny/") + file));
    EXPECT_EQ(scene.stats().triangles, triangles) << file;
  }
}

TEST(AssimpLoader, UtahTeapotObjWithTexture) {
  // README: 8,028 faces (triangles and quads) making 15,704 triangles; map_Kd default.png 128².
  Scene scene = load_with_assimp(test::data_path("meshes/teapot/teapot.obj"));
  EXPECT_EQ(scene.stats().triangles, 15704u);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].width, 128);
  EXPECT_EQ(scene.textures[0].height, 128);
  bool textured = false;
  for (const Material& m : scene.materials)
    if (auto* p = std::get_if<PhongMaterial>(&m.model)) textured |= p->diffuse_texture.valid();
  EXPECT_TRUE(textured);
  for (const Mesh& m : scene.meshes) EXPECT_EQ(m.uvs.size(), m.positions.size());
}

TEST(AssimpLoader, MoriKnobMaterials) {
  // README: 11,970 triangles, 5 materials, one of them emissive.
  Scene scene = load_with_assimp(test::data_path("meshes/mori_knob/testObj.obj"));
  EXPECT_EQ(scene.stats().triangles, 11970u);
  EXPECT_EQ(scene.stats().materials, 5u);
  int emissive = 0;
  for (const Material& m : scene.materials) emissive += !m.emission.is_black();
  EXPECT_EQ(emissive, 1);
}

TEST(AssimpLoader, MtlBecomesPhong) {
  // cornell_box_measured.mtl: white Kd 0.725 0.71 0.68; light Kd 0.78, Ke 17 12 4.
  Scene scene =
      load_with_assimp(test::source_path("scenes/assets/cornell/cornell_box_measured.obj"));
  EXPECT_EQ(scene.stats().triangles, 32u);
  std::map<std::string, const Material*> by_name;
  for (const Material& m : scene.materials) by_name[m.name] = &m;
  ASSERT_TRUE(by_name.count("white") && by_name.count("light"));
  const auto& white = std::get<PhongMaterial>(by_name["white"]->model);
  EXPECT_EQ(white.diffuse, Rgb(0.725f, 0.71f, 0.68f));
  EXPECT_EQ(white.specular, Rgb(0.f));
  EXPECT_EQ(by_name["light"]->emission, Rgb(17.f, 12.f, 4.f));
  EXPECT_EQ(std::get<PhongMaterial>(by_name["light"]->model).diffuse, Rgb(0.78f));
  // Millimetres, as published: the box is 556 wide.
  EXPECT_NEAR(scene.bounds().diagonal().x, 556, 1e-3);
}

class AssimpBadInput : public testing::Test {
 protected:
  std::string dir = test::make_temp_dir("obscura-assimp");
  std::string write(const std::string& name, const std::string& text) {
    std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  void expect_error(const std::string& path, const std::vector<std::string>& fragments) {
    try {
      load_with_assimp(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const Error& e) {
      for (const std::string& f : fragments) EXPECT_THAT(e.what(), testing::HasSubstr(f));
    }
  }
};

TEST_F(AssimpBadInput, MissingFile) {
  expect_error(dir + "/none.obj", {"none.obj", "does not exist"});
}

TEST_F(AssimpBadInput, ObjFaceIndexPastTheVertexCount) {
  expect_error(write("face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), {"face.obj"});
}

TEST_F(AssimpBadInput, PlyFaceIndexPastTheVertexCount) {
  expect_error(write("face.ply",
                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
               {"face.ply"});
}

TEST_F(AssimpBadInput, NanPositions) {
  expect_error(write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
               {"nan.obj", "not finite"});
}

TEST_F(AssimpBadInput, MissingTexture) {
  write("m.mtl", "newmtl paint\nKd 1 1 1\nmap_Kd missing.png\n");
  expect_error(write("tex.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl paint\nf 1 2 3\n"),
               {"tex.obj", "paint", "missing.png", "does not exist"});
}

TEST_F(AssimpBadInput, NotAMesh) {
  expect_error(write("junk.ply", "this is not a ply file\n"), {"junk.ply"});
}

}  // namespace
}  // namespace obscura

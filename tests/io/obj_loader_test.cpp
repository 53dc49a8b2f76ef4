// The OBJ/MTL loader against hand-written files whose geometry and materials are known, the
// test meshes' published counts (tests/data/README.md, scenes/assets/README.md), and bad input.
#include "obscura/io/obj_loader.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>

#include "mesh_test_files.h"
#include "obscura/io/model_file.h"
#include "test_paths.h"

namespace obscura {
namespace {

using test::expect_load_error;

class ObjLoader : public test::TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    return test::write_file(dir_, name, text);
  }
  static const PhongMaterial& phong(const Material& m) { return std::get<PhongMaterial>(m.model); }
};

TEST_F(ObjLoader, UnitSquareQuadWithUvsAndNormals) {
  Scene s = load_obj(write("square.obj",
                           "# a unit square in z = 0, facing +z\n"
                           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                           "f 1/1/1 2/2/1 3/3/1 4/4/1\n"));
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.name, "defaultobject");
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));  // fan from the first corner
  EXPECT_EQ(m.positions[2], Point3f(1, 1, 0));
  // v is flipped to glTF's convention: the file's (1, 1) is the image's top-right, (1, 0).
  EXPECT_EQ(m.uvs[2], Point2f(1, 0));
  EXPECT_EQ(m.uvs[0], Point2f(0, 1));
  for (const Normal3f& n : m.normals) EXPECT_EQ(n, Normal3f(0, 0, 1));
  EXPECT_TRUE(m.colors.empty());
  ASSERT_EQ(s.instances.size(), 1u);
  EXPECT_EQ(s.name, "square");
  // No mtllib: Assimp's default material, Kd 0.6.
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "DefaultMaterial");
  EXPECT_EQ(phong(s.materials[0]).diffuse, Rgb(0.6f));
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_NEAR(s.bounds().diagonal().x, 1, 0);
}

TEST_F(ObjLoader, NegativeIndicesCountFromTheEnd) {
  Scene s = load_obj(write("relative.obj",
                           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n"
                           "v 5 5 5\nf -5 -4 -1\n"));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangle_count(), 3u);
  EXPECT_EQ(s.meshes[0].positions[s.meshes[0].indices[8]], Point3f(5, 5, 5));
}

TEST_F(ObjLoader, PolygonsAreFanTriangulatedAndLinesDropped) {
  Scene s = load_obj(write("pentagon.obj",
                           "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\n"
                           "f 1 2 3 4 5\nl 1 2\nf 1 2\np 3\n"));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
}

TEST_F(ObjLoader, ConcaveQuadIsSplitFromItsReflexCorner) {
  // An arrowhead with its notch at corner 2 (1, 0.3): the fan from corner 1 would cover the notch
  // and leave part of the quad empty; the diagonal from the notch covers exactly the quad.
  Scene s = load_obj(write("dart.obj", "v 0 0 0\nv 1 0.3 0\nv 2 0 0\nv 1 2 0\nf 1 2 3 4\n"));
  EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{1, 2, 3, 1, 3, 0}));
}

TEST_F(ObjLoader, ObjectsGroupsAndMaterialsBecomeMeshesAsAssimpMadeThem) {
  write("g.mtl",
        "newmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 20\n"
        "newmtl blue\nKd 0 0 1\nKe 1 2 3\n"
        "newmtl unused\nKd 0 1 0\n");
  Scene s = load_obj(write("groups.obj",
                           "mtllib g.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                           "o first\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 3 4\n"
                           "g second\nf 1 2 3\n"
                           "o third\nusemtl red\nf 1 2 4\nf 2 3 4\n"));
  // Materials some mesh uses, in library order; the unused one is dropped.
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "red");
  EXPECT_EQ(phong(s.materials[0]).diffuse, Rgb(1, 0, 0));
  EXPECT_EQ(phong(s.materials[0]).specular, Rgb(0.5f));
  EXPECT_EQ(phong(s.materials[0]).shininess, 20);
  EXPECT_EQ(s.materials[1].name, "blue");
  EXPECT_EQ(s.materials[1].emission, Rgb(1, 2, 3));
  // One mesh per object and material; a later material's mesh is named after the material.
  std::vector<std::string> meshes, instances;
  std::vector<uint32_t> materials;
  for (const Mesh& m : s.meshes) meshes.push_back(m.name), materials.push_back(m.material);
  for (const Instance& i : s.instances) instances.push_back(i.name);
  EXPECT_EQ(meshes, (std::vector<std::string>{"first", "blue", "second", "third"}));
  EXPECT_EQ(instances, (std::vector<std::string>{"first", "first", "second", "third"}));
  EXPECT_EQ(materials, (std::vector<uint32_t>{0, 1, 1, 0}));
  EXPECT_EQ(s.meshes[3].triangle_count(), 2u);
  EXPECT_EQ(s.meshes[3].vertex_count(), 4u);
}

TEST_F(ObjLoader, MtlColoursTexturesAndOptions) {
  std::filesystem::copy_file(test::data_path("meshes/teapot/default.png"), dir_ + "/tex.png");
  write("m.mtl",
        "# comment\nnewmtl paint\n  Ka 0.1 0.2 0.3\n  Kd 0.5\n  Ks 0.25 0.25 0.25\n  Ns -4\n"
        "  illum 2\n  map_Kd -s 2 2 1 -clamp on tex.png\n  map_Ke tex.png\n  Ke 1 1 1\n");
  Scene s = load_obj(write("tex.obj",
                           "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                           "usemtl paint\nf 1/1 2/1 3/1\n"));
  ASSERT_EQ(s.materials.size(), 1u);
  const PhongMaterial& p = phong(s.materials[0]);
  EXPECT_EQ(p.ambient, Rgb(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(p.diffuse, Rgb(0.5f));  // "Kd r": g and b default to r (MTL specification)
  EXPECT_EQ(p.specular, Rgb(0.25f));
  EXPECT_EQ(p.shininess, 0);         // negative exponents clamp to 0
  ASSERT_EQ(s.textures.size(), 1u);  // one image, shared by both slots
  EXPECT_EQ(s.textures[0].width, 128);
  EXPECT_EQ(p.diffuse_texture.texture, 0);
  EXPECT_EQ(s.materials[0].emission_texture.texture, 0);
}

TEST_F(ObjLoader, DissolveIsReadAndReportedNotRendered) {
  write("d.mtl", "newmtl glass\nd 0.25\n");
  Scene s = load_obj(write("d.obj",
                           "mtllib d.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl glass\n"
                           "f 1 2 3\n"));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_THAT(s.warnings[0], testing::HasSubstr("glass"));
  EXPECT_THAT(s.warnings[0], testing::HasSubstr("transparent"));
}

TEST_F(ObjLoader, MissingMtllibIsOneWarningAndTheDefaultMaterial) {
  Scene s = load_obj(write("nomtl.obj",
                           "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"
                           "usemtl foo\nf 1 2 3\nf 3 2 1\n"));
  int library_warnings = 0;
  for (const std::string& w : s.warnings)
    if (w.find("missing.mtl") != std::string::npos) {
      ++library_warnings;
      EXPECT_THAT(w, testing::HasSubstr("nomtl.obj:1"));
    }
  EXPECT_EQ(library_warnings, 1);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "foo");  // the name is kept, the values are the default's
  EXPECT_EQ(phong(s.materials[0]).diffuse, Rgb(0.6f));
  EXPECT_EQ(s.meshes[0].triangle_count(), 2u);
}

TEST_F(ObjLoader, VertexColoursAndRepeatedPositionsShareVertices) {
  Scene s = load_obj(write("c.obj",
                           "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\n"
                           "v 0 0 0 1 0 0\nf 1 2 3\nf 4 3 2\n"));
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.vertex_count(), 3u);  // v 4 repeats v 1, as Assimp's vertex joining merged it
  ASSERT_EQ(m.colors.size(), 3u);
  EXPECT_EQ(m.colors[0], Rgb(1, 0, 0));
  EXPECT_EQ(m.colors[2], Rgb(0, 0, 1));
}

TEST_F(ObjLoader, NormalsAreNormalisedAndMissingOnesComeFromTheFaces) {
  Scene s = load_obj(write("n.obj",
                           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 2\n"
                           "f 1//1 2//1 3//1\nf 1 3 4\n"));
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const Normal3f& n : m.normals) EXPECT_EQ(n, Normal3f(0, 0, 1));
}

TEST_F(ObjLoader, FilesLargerThanTheReadChunk) {
  // load_obj streams the file in 1 MiB chunks: lines across chunk boundaries, a 3 MiB comment
  // line and CRLF endings must read as they do from memory. A strip of 2·n triangles.
  const int n = 40000;
  std::string text = "# " + std::string(3 << 20, 'x') + "\r\n";
  for (int i = 0; i <= n; ++i)
    text += "v " + std::to_string(i) + " 0 0\r\nv " + std::to_string(i) + " 1 0.5\r\n";
  for (int i = 0; i < n; ++i) {
    int a = 2 * i + 1;
    text += "f " + std::to_string(a) + " " + std::to_string(a + 2) + " " + std::to_string(a + 3) +
            " " + std::to_string(a + 1) + "\r\n";
  }
  Scene s = load_obj(write("strip.obj", text));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangle_count(), size_t(2 * n));
  EXPECT_EQ(s.meshes[0].vertex_count(), size_t(2 * n + 2));
  EXPECT_EQ(s.bounds().diagonal(), Vector3f(n, 1, 0.5f));
  // An error's line number counts every line, across chunks.
  expect_load_error([&] { load_obj(write("bad.obj", text + "f 1 2 x\n")); },
                    {"bad.obj:" + std::to_string(1 + 2 * (n + 1) + n + 1)});
}

TEST_F(ObjLoader, UtahTeapotWithTexture) {
  // tests/data/README.md: 8,028 faces (triangles and quads) making 15,704 triangles; map_Kd
  // default.png, 128².
  Scene s = load_obj(test::data_path("meshes/teapot/teapot.obj"));
  EXPECT_EQ(s.stats().triangles, 15704u);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].height, 128);
  EXPECT_EQ(s.meshes.size(), 2u);  // groups Base and Top
  for (const Mesh& m : s.meshes) EXPECT_EQ(m.uvs.size(), m.positions.size());
  EXPECT_TRUE(phong(s.materials[0]).diffuse_texture.valid());
}

TEST_F(ObjLoader, MoriKnobAndCornellBox) {
  // README: 11,970 triangles, 5 materials, one emissive.
  Scene knob = load_obj(test::data_path("meshes/mori_knob/testObj.obj"));
  EXPECT_EQ(knob.stats().triangles, 11970u);
  EXPECT_EQ(knob.stats().materials, 5u);
  // cornell_box_measured.mtl: white Kd 0.725 0.71 0.68; light Kd 0.78, Ke 17 12 4; 32 triangles,
  // 556 mm wide.
  Scene box = load_obj(test::source_path("scenes/assets/cornell/cornell_box_measured.obj"));
  EXPECT_EQ(box.stats().triangles, 32u);
  std::map<std::string, const Material*> by_name;
  for (const Material& m : box.materials) by_name[m.name] = &m;
  ASSERT_TRUE(by_name.count("white") && by_name.count("light"));
  EXPECT_EQ(phong(*by_name["white"]).diffuse, Rgb(0.725f, 0.71f, 0.68f));
  EXPECT_EQ(by_name["light"]->emission, Rgb(17.f, 12.f, 4.f));
  EXPECT_NEAR(box.bounds().diagonal().x, 556, 1e-3);
}

TEST_F(ObjLoader, SceneLoaderRoutesObjHere) {
  // load_model_file picks this loader by extension: the warning is this loader's wording.
  Scene s = load_model_file(write("r.obj",
                                  "mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "f 1 2 3\n"));
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_THAT(s.warnings[0], testing::HasSubstr("material library 'none.mtl' not found"));
}

TEST_F(ObjLoader, IndicesOutOfRangeNameFileAndLine) {
  std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  expect_load_error([&] { load_obj(write("a.obj", v + "f 1 2 9\n")); }, {"a.obj:6", "vertex 9"});
  expect_load_error([&] { load_obj(write("b.obj", v + "f 1/2 2/1 3/1\n")); },
                    {"b.obj:6", "texture coordinate 2"});
  expect_load_error([&] { load_obj(write("c.obj", v + "\nf 1//1 2//1 3//-2\n")); },
                    {"c.obj:7", "normal -2"});
  expect_load_error([&] { load_obj(write("d.obj", v + "f 0 1 2\n")); }, {"d.obj:6", "vertex 0"});
  expect_load_error([&] { load_obj(write("e.obj", v + "f 1 2 -4\n")); }, {"e.obj:6"});
  expect_load_error([&] { load_obj(write("f.obj", v + "f 1 2 x\n")); }, {"f.obj:6", "'x'"});
  // A forward reference: the vertex is defined later.
  expect_load_error([&] { load_obj(write("g.obj", "f 1 2 3\n" + v)); }, {"g.obj:1"});
}

TEST_F(ObjLoader, MalformedStatementsNameFileAndLine) {
  expect_load_error([&] { load_obj(write("a.obj", "v 0 0\n")); }, {"a.obj:1", "v X Y Z"});
  expect_load_error([&] { load_obj(write("b.obj", "v 0 0 0\nv nan 0 0\n")); },
                    {"b.obj:2", "not finite"});
  expect_load_error([&] { load_obj(write("c.obj", "vn 0 0 1e99\n")); }, {"c.obj:1", "not finite"});
  write("bad.mtl", "newmtl m\nKd 1 x 1\n");
  expect_load_error([&] { load_obj(write("d.obj", "mtllib bad.mtl\n")); }, {"bad.mtl:2", "Kd"});
  write("neg.mtl", "newmtl m\nKe -1 0 0\n");
  expect_load_error([&] { load_obj(write("e.obj", "mtllib neg.mtl\n")); },
                    {"neg.mtl:2", "non-negative"});
}

// Downloaded OBJs often name textures that are not there, name them by a path on the author's
// machine, or use formats we do not read (DDS): as in glTF, each warns once, naming the material
// and the file; a diffuse map shows the magenta/black checker, an emission map is left out, and
// a file found next to the model under its base name is used.
TEST_F(ObjLoader, UnusableTexturesWarnAndShowTheChecker) {
  std::filesystem::copy_file(test::data_path("meshes/teapot/default.png"), dir_ + "/near.png");
  write("fake.dds", "DDS |not really an image");
  write("m.mtl",
        "newmtl paint\nKd 1 1 1\nmap_Kd missing.png\n"
        "newmtl glow\nKe 1 1 1\nmap_Ke fake.dds\nmap_Kd fake.dds\n"
        "newmtl wood\nmap_Kd C:\\Users\\someone\\textures\\near.png\n");
  const Scene s = load_obj(write("tex.obj",
                                 "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                                 "usemtl paint\nf 1/1 2/1 3/1\nusemtl glow\nf 1/1 2/1 3/1\n"
                                 "usemtl wood\nf 1/1 2/1 3/1\n"));
  auto material = [&](const std::string& name) -> const Material& {
    for (const Material& m : s.materials)
      if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
  };
  auto texture_name = [&](TextureRef ref) {
    return ref.valid() ? s.textures[size_t(ref.texture)].name : std::string("(none)");
  };
  EXPECT_EQ(texture_name(phong(material("paint")).diffuse_texture), "missing-image placeholder");
  EXPECT_EQ(texture_name(phong(material("glow")).diffuse_texture), "missing-image placeholder");
  EXPECT_FALSE(material("glow").emission_texture.valid());
  const TextureRef wood = phong(material("wood")).diffuse_texture;
  ASSERT_TRUE(wood.valid());
  EXPECT_EQ(s.textures[size_t(wood.texture)].width, 128);  // the real image, found next to it
  // One warning per unusable file, naming the material and the file; one for the file found.
  auto warnings_naming = [&](const std::string& a, const std::string& b) {
    int n = 0;
    for (const std::string& w : s.warnings)
      if (w.find(a) != std::string::npos && w.find(b) != std::string::npos) ++n;
    return n;
  };
  EXPECT_EQ(warnings_naming("'paint'", "missing.png"), 1);
  EXPECT_EQ(warnings_naming("'glow'", "fake.dds"), 1);
  EXPECT_EQ(warnings_naming("'wood'", "found next to the model"), 1);
  // The checker is made once, whatever number of materials need it.
  int checkers = 0;
  for (const Texture& t : s.textures) checkers += t.name == "missing-image placeholder";
  EXPECT_EQ(checkers, 1);
}

TEST_F(ObjLoader, NotARegularFile) {
  expect_load_error([&] { load_obj(dir_ + "/none.obj"); }, {"none.obj", "does not exist"});
  expect_load_error([&] { load_obj(dir_); }, {"directory"});
  expect_load_error([&] { load_obj("/dev/zero"); }, {"/dev/zero", "not a regular file"});
}

TEST_F(ObjLoader, TruncatedTeapotNeverCrashes) {
  // An OBJ cut at a line boundary is a valid, smaller OBJ; cut inside a line it is either valid
  // or an error naming the line. Either way: no crash, no hang.
  std::string text = test::read_file(test::data_path("meshes/teapot/teapot.obj"));
  write("default.mtl", test::read_file(test::data_path("meshes/teapot/default.mtl")));
  std::filesystem::copy_file(test::data_path("meshes/teapot/default.png"), dir_ + "/default.png");
  int errors = 0, loaded = 0;
  for (size_t cut = 1; cut < text.size(); cut += text.size() / 97) {
    std::string path = write("cut.obj", text.substr(0, cut) + "/");  // a dangling corner
    try {
      Scene s = load_obj(path);
      s.validate();
      ++loaded;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr("cut.obj:"));
      ++errors;
    }
  }
  EXPECT_GT(errors + loaded, 90);
}

}  // namespace
}  // namespace obscura

// The STL loader against hand-written unit squares (ASCII, and binary whose header starts with
// "solid"), and hostile input: truncation at many cut points and triangle counts that lie.
#include "obscura/io/stl_loader.h"

#include <sys/stat.h>

#include "mesh_test_files.h"
#include "obscura/io/model_file.h"
#include "test_paths.h"

namespace obscura {
namespace {

using test::expect_load_error;
using test::put;

class StlLoader : public test::TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& bytes) {
    return test::write_file(dir_, name, bytes);
  }
};

const char* kSquareAscii =
    "solid square\n"
    "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
    "      vertex 1 1 0\n    endloop\n  endfacet\n"
    "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 1 0\n"
    "      vertex 0 1 0\n    endloop\n  endfacet\n"
    "endsolid square\n";

// The same square in binary, with an 80-byte header that starts with "solid" (as many
// exporters write) and, if asked, a zero normal on the second facet.
std::string square_binary(bool zero_second_normal = false, uint32_t declared = 2) {
  std::string out = "solid square exported by a CAD program";
  out.resize(80, ' ');
  put(out, declared);
  float triangles[2][4][3] = {
      {{0, 0, 1}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}},
      {{0, 0, zero_second_normal ? 0.f : 1.f}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  for (auto& t : triangles) {
    for (auto& v : t)
      for (float f : v) put(out, f);
    put(out, uint16_t(0));
  }
  return out;
}

void expect_unit_square(const Scene& s) {
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.triangle_count(), 2u);
  ASSERT_EQ(m.vertex_count(), 4u);  // corners shared where position and normal agree
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(m.positions[3], Point3f(0, 1, 0));
  ASSERT_EQ(m.normals.size(), 4u);
  for (const Normal3f& n : m.normals) EXPECT_EQ(n, Normal3f(0, 0, 1));
  ASSERT_EQ(s.instances.size(), 1u);
  ASSERT_EQ(s.materials.size(), 1u);
}

TEST_F(StlLoader, UnitSquareAscii) {
  Scene s = load_stl(write("square.stl", kSquareAscii));
  expect_unit_square(s);
  EXPECT_EQ(s.meshes[0].name, "square");
  EXPECT_EQ(s.name, "square");
}

TEST_F(StlLoader, UnitSquareBinaryStartingWithSolid) {
  Scene s = load_stl(write("square.stl", square_binary()));
  expect_unit_square(s);
  // A zero facet normal is replaced by the triangle's own (+z here, counter-clockwise).
  expect_unit_square(load_stl(write("zero.stl", square_binary(true))));
}

TEST_F(StlLoader, AsciiVariants) {
  // Capitalised keywords, CRLF, no solid name, two solids.
  std::string text =
      "SOLID\r\nFACET NORMAL 0 0 0\r\nOUTER LOOP\r\nVERTEX 0 0 0\r\nVERTEX 2 0 0\r\n"
      "VERTEX 0 2 0\r\nENDLOOP\r\nENDFACET\r\nENDSOLID\r\n"
      "solid second\nfacet normal 1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\n"
      "vertex 0 0 1\nendloop\nendfacet\nendsolid second\n";
  Scene s = load_stl(write("two.stl", text));
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].name, "mesh 0");
  EXPECT_EQ(s.meshes[1].name, "second");
  EXPECT_EQ(s.meshes[0].normals[0], Normal3f(0, 0, 1));  // computed: the file's was zero
  EXPECT_EQ(s.meshes[1].normals[0], Normal3f(1, 0, 0));
}

TEST_F(StlLoader, LyingTriangleCountIsRefused) {
  // 2^32 − 1 triangles declared in a 184-byte file.
  expect_load_error([&] { load_stl(write("lie.stl", square_binary(false, 0xFFFFFFFFu))); },
                    {"lie.stl", "4294967295 triangles", "184"});
  expect_load_error([&] { load_stl(write("three.stl", square_binary(false, 3))); },
                    {"three.stl", "3 triangles"});
}

TEST_F(StlLoader, TruncatedAtManyCutPointsIsAnError) {
  std::string binary = square_binary();
  for (size_t cut = 1; cut < binary.size(); ++cut) {
    std::string path = write("cut.stl", binary.substr(0, cut));
    expect_load_error([&] { load_stl(path); }, {"cut.stl"});
  }
  std::string ascii = kSquareAscii;
  size_t complete = ascii.rfind("endsolid");  // a cut after this is a complete file
  for (size_t cut = 1; cut <= complete; ++cut) {
    std::string path = write("cut.stl", ascii.substr(0, cut));
    expect_load_error([&] { load_stl(path); }, {"cut.stl"});
  }
}

TEST_F(StlLoader, MalformedAsciiNamesTheLine) {
  std::string text = kSquareAscii;
  text.replace(text.find("vertex 1 0 0"), 12, "vertex 1 x 0");
  expect_load_error([&] { load_stl(write("a.stl", text)); }, {"a.stl:5", "vertex X Y Z"});
  text = kSquareAscii;
  text.replace(text.find("vertex 1 0 0"), 12, "vertex 1 nan 0");
  expect_load_error([&] { load_stl(write("b.stl", text)); }, {"b.stl:8", "not finite"});
  expect_load_error(
      [&] {
        load_stl(write("c.stl",
                       "solid x\nfacet normal 0 0 1\nouter loop\n"
                       "vertex 0 0 0\nvertex 0 0 0\nvertex 0 0 0\n"
                       "vertex 0 0 0\n"));
      },
      {"c.stl:7", "more than 3"});
  expect_load_error([&] { load_stl(write("d.stl", "solid x\nbanana\nendsolid\n")); },
                    {"d.stl:2", "banana"});
  expect_load_error([&] { load_stl(write("e.stl", "")); }, {"e.stl", "empty"});
}

TEST_F(StlLoader, FifoDeviceAndDirectoryAreRefusedWithoutReading) {
  // Read forever (a FIFO no one writes, /dev/zero) if opened: refused from the file's type.
  std::string fifo = dir_ + "/pipe.stl";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expect_load_error([&] { load_stl(fifo); }, {"pipe.stl", "not a regular file"});
  expect_load_error([&] { load_stl("/dev/zero"); }, {"/dev/zero", "not a regular file"});
  expect_load_error([&] { load_stl(dir_); }, {"directory"});
  expect_load_error([&] { load_stl(dir_ + "/none.stl"); }, {"none.stl", "does not exist"});
}

TEST_F(StlLoader, SceneLoaderRoutesStlHere) {
  Scene s = load_model_file(write("r.stl", square_binary()));
  expect_unit_square(s);
  expect_load_error([&] { load_model_file(write("t.stl", square_binary().substr(0, 120))); },
                    {"t.stl", "declares 2 triangles"});
}

}  // namespace
}  // namespace obscura

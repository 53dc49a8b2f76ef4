// The OBJ reader on files of many blocks (io/text_blocks.h cuts text into blocks of about half a
// megabyte, parsed on several threads): a generated grid whose vertices, texture coordinates and
// faces are known exactly, the same scene for any thread count, and line numbers in messages
// about lines far past the first block.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <map>
#include <string>

#include "mesh_test_files.h"
#include "obscura/io/obj_loader.h"
#include "obscura/io/text_blocks.h"

namespace obscura {
namespace {

using test::expect_load_error;

// An n × n quad grid, two triangles per quad, with one texture coordinate per vertex and one
// normal. Every value is a multiple of a power of two written with all its digits, so the
// decimal text is exactly the float: the expected values need no parser.
struct Grid {
  int n;
  int vertices() const { return (n + 1) * (n + 1); }
  // Vertex k (0-based, row-major) as written.
  Point3f position(int k) const {
    int i = k % (n + 1), j = k / (n + 1);
    return {float(i) * 0.25f, float(j) * 0.5f, float((i + j) % 3) * 0.125f};
  }
  Point2f uv(int k) const {  // as written: 1/512 steps
    int i = k % (n + 1), j = k / (n + 1);
    return {float(i) / 512, float(j) / 512};
  }
  // The corners (0-based vertex numbers) of triangle t, in the order the file lists them.
  std::array<int, 3> triangle(int t) const {
    int quad = t / 2, i = quad % n, j = quad / n;
    int a = j * (n + 1) + i, b = a + 1, c = b + n + 1, d = a + n + 1;
    return t % 2 == 0 ? std::array<int, 3>{a, b, c} : std::array<int, 3>{a, c, d};
  }
  // Lines before the first face: v, vt, then one vn.
  int first_face_line() const { return 2 * vertices() + 2; }

  std::string text() const {
    std::string out;
    char line[96];
    for (int k = 0; k < vertices(); ++k) {
      Point3f p = position(k);
      std::snprintf(line, sizeof line, "v %.5f %.5f %.5f\n", p.x, p.y, p.z);
      out += line;
    }
    for (int k = 0; k < vertices(); ++k) {
      Point2f t = uv(k);
      std::snprintf(line, sizeof line, "vt %.9f %.9f\n", t.x, t.y);
      out += line;
    }
    out += "vn 0 0 1\n";
    for (int t = 0; t < 2 * n * n; ++t) {
      auto c = triangle(t);
      std::snprintf(line, sizeof line, "f %d/%d/1 %d/%d/1 %d/%d/1\n", c[0] + 1, c[0] + 1, c[1] + 1,
                    c[1] + 1, c[2] + 1, c[2] + 1);
      out += line;
    }
    return out;
  }
};

class ObjBlocks : public test::TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    return test::write_file(dir_, name, text);
  }
  // 150 × 150 quads: 2.3 MB of text, five blocks.
  Grid grid_{150};
};

TEST_F(ObjBlocks, GridMatchesItsAnalyticVertices) {
  const std::string text = grid_.text();
  ASSERT_GT(text.size(), 4 * TextBlocks::kBlockBytes);
  Scene s = load_obj(write("grid.obj", text));
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.indices.size(), size_t(3 * 2 * grid_.n * grid_.n));
  ASSERT_EQ(m.positions.size(), size_t(grid_.vertices()));
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  ASSERT_EQ(m.normals.size(), m.positions.size());
  // Mesh vertices are numbered in order of first use (obj_loader.h): the reference numbering
  // walks the faces as written.
  std::map<int, uint32_t> vertex_of;
  for (int t = 0; t < 2 * grid_.n * grid_.n; ++t)
    for (int k = 0; k < 3; ++k) {
      int written = grid_.triangle(t)[k];
      auto [it, added] = vertex_of.emplace(written, uint32_t(vertex_of.size()));
      ASSERT_EQ(m.indices[3 * t + k], it->second) << "triangle " << t << " corner " << k;
      if (!added) continue;
      ASSERT_EQ(m.positions[it->second], grid_.position(written)) << "vertex " << written;
      Point2f uv = grid_.uv(written);
      ASSERT_EQ(m.uvs[it->second], Point2f(uv.x, 1 - uv.y)) << "vertex " << written;
      ASSERT_EQ(m.normals[it->second], Normal3f(0, 0, 1));
    }
}

TEST_F(ObjBlocks, SameSceneForAnyThreadCountAndFromMemory) {
  const std::string text = grid_.text();
  const std::string path = write("grid.obj", text);
  auto load_with = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    return load_obj(path);
  };
  Scene one = load_with(1);
  for (int threads : {2, 3, 8}) {
    Scene other = load_with(threads);
    ASSERT_EQ(other.meshes.size(), 1u);
    EXPECT_EQ(other.meshes[0].indices, one.meshes[0].indices) << threads << " threads";
    EXPECT_EQ(other.meshes[0].positions, one.meshes[0].positions) << threads << " threads";
    EXPECT_EQ(other.meshes[0].uvs, one.meshes[0].uvs) << threads << " threads";
  }
  Scene memory = load_obj_bytes(std::span<const char>(text.data(), text.size()), path, dir_);
  EXPECT_EQ(memory.meshes[0].indices, one.meshes[0].indices);
  EXPECT_EQ(memory.meshes[0].positions, one.meshes[0].positions);
}

TEST_F(ObjBlocks, ErrorsFarPastTheFirstBlockNameTheirLine) {
  const std::string text = grid_.text();
  const int faces = 2 * grid_.n * grid_.n;
  const int last_line = grid_.first_face_line() + faces - 1;
  // An index past the vertices, and a malformed index, each on the line after the grid.
  const std::string bad_index = std::to_string(grid_.vertices() + 1);
  expect_load_error([&] { load_obj(write("a.obj", text + "f 1 2 " + bad_index + "\n")); },
                    {"a.obj:" + std::to_string(last_line + 1) + ":", "vertex " + bad_index,
                     std::to_string(grid_.vertices()) + " vertexs are defined"});
  expect_load_error(
      [&] { load_obj(write("b.obj", text + "\n\nf 1 2 x3\n")); },
      {"b.obj:" + std::to_string(last_line + 3) + ":", "malformed face corner index 'x3'"});
  // The same from memory, without a final newline.
  std::string bytes = text + "v 1 2 inf";
  expect_load_error(
      [&] { load_obj_bytes(std::span<const char>(bytes.data(), bytes.size()), "c.obj", dir_); },
      {"c.obj:" + std::to_string(last_line + 1) + ":", "not finite"});
}

TEST_F(ObjBlocks, LinesLongerThanABlockAndCarriageReturns) {
  // A comment longer than two blocks, then a triangle in CRLF lines, the last without a newline.
  std::string text = "# ";  // appended: GCC 12 -O3 warns falsely on "lit" + std::string
  text += std::string(2 * TextBlocks::kBlockBytes + 100, 'x');
  text += "\r\n";
  text += "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3";
  for (bool from_file : {true, false}) {
    Scene s = from_file
                  ? load_obj(write("long.obj", text))
                  : load_obj_bytes(std::span<const char>(text.data(), text.size()), "long", dir_);
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].positions, (std::vector<Point3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2}));
  }
  expect_load_error([&] { load_obj(write("long2.obj", text + "\r\nf 1 2 4\r\n")); },
                    {"long2.obj:6:", "vertex 4"});
}

TEST(TextBlocks, EveryByteOnceInWholeLines) {
  // Lines of growing length, some longer than a block: the blocks put the text back together,
  // and each but the last ends at a newline.
  std::string text;
  for (size_t length = 1; text.size() < 3 * TextBlocks::kBlockBytes; length = length * 3 + 1)
    text += std::string(length, 'a') + "\n";
  text += "tail";
  TextBlocks blocks(std::span<const char>(text.data(), text.size()));
  std::string joined;
  TextBlock block;
  int count = 0;
  while (blocks.next(block)) {
    ++count;
    joined += block.text;
    if (joined.size() < text.size()) {
      EXPECT_EQ(block.text.back(), '\n');
    }
  }
  EXPECT_EQ(joined, text);
  EXPECT_GE(count, 3);
}

}  // namespace
}  // namespace obscura

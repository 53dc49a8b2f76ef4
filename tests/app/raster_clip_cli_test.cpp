// `obscura raster-clip`: the conformance format, run as a user would.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "obscura/io/image_io.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class RasterClipCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_temp_dir("obscura-raster-clip"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (fs::path(dir_) / name).string(); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
  }
  static std::vector<int> read_plain_pgm(const std::string& file, int* w, int* h) {
    std::ifstream in(file);
    std::string magic;
    int max_value;
    in >> magic >> *w >> *h >> max_value;
    EXPECT_EQ(magic, "P2");
    std::vector<int> v(size_t(*w) * *h);
    for (int& x : v) in >> x;
    return v;
  }
  std::string dir_;
};

// A 4×2 image (NDC → image: x = 2(ndc_x + 1), y = 1 − ndc_y). Triangles 7 and 8 split the left
// square along its diagonal y = x, which passes through centres (0.5, 0.5) and (1.5, 1.5): they
// belong to the triangle on the diagonal's right, 8. Triangle 9 (depth 0.75) is the lower right
// half of the right square, its diagonal y = 4 − x through centres (3.5, 0.5) and (2.5, 1.5),
// which it owns (it lies right of it). Triangle 5 (depth 0.25, nearer) covers only (3.5, 1.5).
// The fourth triangle's extra vertex is removed for the valid case.
constexpr const char* kScene = R"({
  "name": "halves", "width": 4, "height": 2, "clear_color": [10, 20, 30], "clear_depth": 1.0,
  "depth_func": "LESS", "cull": "none",
  "triangles": [
    {"id": 7, "color": [255, 0, 0], "clip": [[-1, -1, 0, 1], [0, -1, 0, 1], [-1, 1, 0, 1]]},
    {"id": 8, "color": [200, 0, 0], "clip": [[0, -1, 0, 1], [0, 1, 0, 1], [-1, 1, 0, 1]]},
    {"id": 9, "color": [0, 255, 0], "clip": [[0, -1, 0.5, 1], [1, -1, 0.5, 1], [1, 1, 0.5, 1]]},
    {"id": 5, "color": [0, 0, 77], "clip": [[0.5, -1, -0.5, 1], [1, -1, -0.5, 1], [1, 1, -0.5, 1], [9, 9, 9, 9]]}
  ]})";
constexpr const char* kExtraVertex = ", [9, 9, 9, 9]";

TEST_F(RasterClipCli, WritesColoursIdsCountsAndDepth) {
  std::string scene = kScene;
  scene.erase(scene.find(kExtraVertex), std::string(kExtraVertex).size());
  write("halves.json", scene);
  auto result = test::run_cli("raster-clip " + path("halves.json") + " --out " + dir_);
  ASSERT_EQ(result.exit_code, 0) << result.output;

  int w, h;
  EXPECT_EQ(read_plain_pgm(path("halves.ids.pgm"), &w, &h), std::vector<int>({8, 8, 0, 9,  //
                                                                              7, 8, 9, 5}));
  EXPECT_EQ(w, 4);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(read_plain_pgm(path("halves.count.pgm"), &w, &h), std::vector<int>({1, 1, 0, 1,  //
                                                                                1, 1, 1, 2}));

  // The PNG holds the given bytes exactly.
  Image png = read_image(path("halves.png"));
  ASSERT_EQ(png.width, 4);
  ASSERT_EQ(png.height, 2);
  auto bytes = [&](int x, int y) {
    Rgb c = png.rgb(x, y);
    return std::vector<int>{int(std::lround(c.r * 255)), int(std::lround(c.g * 255)),
                            int(std::lround(c.b * 255))};
  };
  EXPECT_EQ(bytes(0, 0), std::vector<int>({200, 0, 0}));
  EXPECT_EQ(bytes(0, 1), std::vector<int>({255, 0, 0}));
  EXPECT_EQ(bytes(2, 0), std::vector<int>({10, 20, 30}));
  EXPECT_EQ(bytes(3, 0), std::vector<int>({0, 255, 0}));
  EXPECT_EQ(bytes(3, 1), std::vector<int>({0, 0, 77}));

  Image depth = read_image(path("halves.depth.pfm"));
  ASSERT_EQ(depth.channels, 1);
  EXPECT_FLOAT_EQ(depth.at(0, 0, 0), 0.5f);
  EXPECT_FLOAT_EQ(depth.at(2, 0, 0), 1.0f);  // clear depth
  EXPECT_FLOAT_EQ(depth.at(3, 0, 0), 0.75f);
  EXPECT_FLOAT_EQ(depth.at(3, 1, 0), 0.25f);
}

TEST_F(RasterClipCli, NamesTheJsonPathOfMalformedInput) {
  write("bad.json", kScene);
  auto result = test::run_cli("raster-clip " + path("bad.json") + " --out " + dir_);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("triangles[3].clip"), std::string::npos) << result.output;
  write("bad2.json", R"({"name": "x", "width": 0, "height": 2, "triangles": []})");
  result = test::run_cli("raster-clip " + path("bad2.json") + " --out " + dir_);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("width"), std::string::npos) << result.output;
  write("bad3.json",
        R"({"name": "x", "width": 2, "height": 2, "depth_func": "SOMETIMES", "triangles": []})");
  result = test::run_cli("raster-clip " + path("bad3.json") + " --out " + dir_);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("depth_func"), std::string::npos) << result.output;
  result = test::run_cli("raster-clip " + path("bad.json"));
  EXPECT_EQ(result.exit_code, 2) << "missing --out is a usage error";
}

// Under a file-size limit (failing like a full disk) the outputs fail whole: exit 1 naming the
// file, and no temporary file left in the output directory.
TEST_F(RasterClipCli, FailedWriteLeavesNoTemporaryFiles) {
  write("big.json", R"({"name": "big", "width": 96, "height": 96, "triangles": [
    {"id": 3, "color": [255, 0, 0], "clip": [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]}]})");
  std::string command(1, '\'');
  command.append(test::cli_path()).append("' raster-clip " + path("big.json") + " --out " + dir_);
  auto result = test::run_shell("ulimit -f 1; " + command);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("File too large"), std::string::npos) << result.output;
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find("tmp"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace obscura

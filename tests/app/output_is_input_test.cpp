// `render -o FILE` refuses to write over any file the scene reads — the scene file, models,
// glTF buffers and images, textures, the environment map — compared by file identity, so another
// spelling of the path, a symbolic link or a hard link is caught as well.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/mesh_test_files.h"
#include "obscura/io/image_io.h"
#include "obscura/io/scene_loader.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class OutputIsInput : public test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    // A copy: should a refusal fail, only the copy is overwritten, never the suite's data.
    fs::copy(test::data_path("gltf/BoxTextured/glTF"), dir_);
    fs::create_directory(path("sub"));
  }
  // Renders `scene` to `output` (tiny and fast); the file must be refused and left as it was.
  void expect_refused(const std::string& scene, const std::string& output,
                      const std::string& input_named, const std::string& extra = "") {
    std::string before = test::read_file(path(input_named));
    auto r = test::run_cli("render " + scene + " -o " + output +
                           " --width 8 --height 8 --spp 1 -q " + extra);
    EXPECT_EQ(r.exit_code, 1) << output << ": " << r.output;
    EXPECT_NE(r.output.find(input_named), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("input"), std::string::npos) << r.output;
    EXPECT_EQ(test::read_file(path(input_named)), before) << output;
  }
};

TEST_F(OutputIsInput, GltfImageIsRefusedUnderAnySpelling) {
  std::string scene = path("BoxTextured.gltf");
  expect_refused(scene, path("CesiumLogoFlat.png"), "CesiumLogoFlat.png");
  expect_refused(scene, path("sub/../CesiumLogoFlat.png"), "CesiumLogoFlat.png");
  fs::create_symlink(path("CesiumLogoFlat.png"), path("link.png"));
  expect_refused(scene, path("link.png"), "CesiumLogoFlat.png");
  fs::create_hard_link(path("CesiumLogoFlat.png"), path("hard.png"));
  expect_refused(scene, path("hard.png"), "CesiumLogoFlat.png");
  auto r = test::run_cli("render " + scene + " -o " + path("out.png") +
                         " --width 8 --height 8 --spp 1 -q");
  EXPECT_EQ(r.exit_code, 0) << r.output;  // any other output is fine
}

TEST_F(OutputIsInput, GltfBufferWithAnImageNameIsRefused) {
  // A buffer may have any name, including one the writer would take.
  std::string gltf = test::read_file(path("BoxTextured.gltf"));
  size_t at = gltf.find("BoxTextured0.bin");
  ASSERT_NE(at, std::string::npos);
  gltf.replace(at, 16, "buffer.pfm");
  std::ofstream(path("renamed.gltf")) << gltf;
  fs::rename(path("BoxTextured0.bin"), path("buffer.pfm"));
  expect_refused(path("renamed.gltf"), path("buffer.pfm"), "buffer.pfm");
}

TEST_F(OutputIsInput, JsonSceneTextureAndEnvironmentMapsAreRefused) {
  Image sky(8, 4, 3);
  sky.data.assign(sky.data.size(), 0.5f);
  write_image(path("sky.exr"), sky);
  write_image(path("tex.png"), sky);
  std::ofstream(path("scene.json")) << R"({
    "materials": {"m": {"type": "diffuse", "reflectance_texture": "tex.png"}},
    "objects": [{"shape": "sphere", "radius": 1, "material": "m"}],
    "environment": {"file": "sky.exr"}
  })";
  expect_refused(path("scene.json"), path("tex.png"), "tex.png");
  expect_refused(path("scene.json"), path("sky.exr"), "sky.exr");
  expect_refused("", path("sky.exr"), "sky.exr", "--environment " + path("sky.exr"));
}

TEST_F(OutputIsInput, AovBesideTheOutputIsRefusedWhenItIsAnInput) {
  // --aovs writes <stem>.albedo/.normal/.depth/.id.exr: an environment map of that name is refused
  // before anything is rendered, for both renderers.
  Image sky(8, 4, 3);
  sky.data.assign(sky.data.size(), 0.5f);
  write_image(path("out.depth.exr"), sky);
  for (const char* renderer : {"path", "raster"})
    expect_refused(
        "", path("out.png"), "out.depth.exr",
        std::string("--aovs --renderer ") + renderer + " --environment " + path("out.depth.exr"));
  EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(OutputIsInput, LoadersRecordEveryFileTheyRead) {
  Scene scene = load_scene_file(path("BoxTextured.gltf"));
  auto recorded = [&](const std::string& name) {
    for (const std::string& f : scene.input_files)
      if (fs::equivalent(f, path(name))) return true;
    return false;
  };
  EXPECT_TRUE(recorded("BoxTextured.gltf"));
  EXPECT_TRUE(recorded("BoxTextured0.bin"));
  EXPECT_TRUE(recorded("CesiumLogoFlat.png"));
  EXPECT_EQ(scene.input_files.size(), 3u);
}

}  // namespace
}  // namespace obscura

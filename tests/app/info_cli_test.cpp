// `obscura info` and scene files on the command line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

TEST(InfoCli, PrintsCountsOfAFile) {
  // scenes/assets/README.md: the bunny at level 2 has 16,301 triangles.
  test::CommandResult r =
      test::run_cli("info " + test::source_path("scenes/assets/bunny/bun_zipper_res2.ply"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, testing::HasSubstr("16,301 rendered"));
  for (const char* field : {"vertices", "instances", "materials", "textures", "lights", "cameras",
                            "bounds", "load time", "memory"})
    EXPECT_THAT(r.output, testing::HasSubstr(field));
}

TEST(InfoCli, BvhBuildsTheTracerSceneAndReportsIt) {
  test::CommandResult r = test::run_cli(
      "info --bvh --threads 1 " + test::source_path("scenes/assets/bunny/bun_zipper_res2.ply"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, testing::HasSubstr("16,301 rendered"));
  EXPECT_THAT(r.output, testing::ContainsRegex("bvh build +[0-9.]+ s \\([0-9.]+ s CPU\\)"));
  EXPECT_THAT(r.output, testing::ContainsRegex("Embree holds [0-9.]+ MB"));
  EXPECT_THAT(r.output, testing::ContainsRegex("MB above the [0-9.]+ MB before loading"));
  r = test::run_cli("info --threads -1 gltf-spheres");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, testing::HasSubstr("--threads"));
}

TEST(InfoCli, BuiltInScenesByName) {
  test::CommandResult r = test::run_cli("info gltf-spheres");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // MetalRoughSpheresNoTextures (1,040,409 triangles) plus the scene's 2-triangle light.
  EXPECT_THAT(r.output, testing::HasSubstr("1,040,411 rendered"));
}

TEST(InfoCli, MissingSceneExitsOne) {
  test::CommandResult r = test::run_cli("info no/such/scene.glb");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, testing::HasSubstr("no/such/scene.glb"));
}

TEST(RenderSceneFileCli, RendersASceneFileAndListsBuiltIns) {
  std::string dir = test::make_temp_dir("obscura-render-file");
  test::CommandResult r =
      test::run_cli("render " + test::data_path("gltf/Box/Box.glb") +
                    " --width 16 --height 16 --spp 1 -q -o " + dir + "/box.png");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cli("render --scene-list");
  for (const char* name : {"cornell-box", "spheres-and-lights", "depth-of-field", "motion-blur",
                           "bunny", "gltf-spheres"})
    EXPECT_THAT(r.output, testing::HasSubstr(name));
}

}  // namespace
}  // namespace obscura

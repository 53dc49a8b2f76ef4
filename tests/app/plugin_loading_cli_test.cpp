// The image codecs (OpenImageIO) and the MPI team are plugins loaded when first needed
// (src/obscura/io/plugin_loader.h): start-up loads neither, a run that writes an image finds the
// codecs, and a missing or broken plugin stops a command before its work with a message naming
// where it looked — never a crash or a partial file.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

using testing::HasSubstr;
using testing::Not;

#ifdef OBSCURA_STATIC_IMAGE_CODECS
constexpr bool kCodecsLinkedIn = true;  // sanitized builds: nothing to load
#else
constexpr bool kCodecsLinkedIn = false;
#endif

class PluginLoadingCli : public test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    if (kCodecsLinkedIn) GTEST_SKIP() << "this build links the image codecs in";
    std::filesystem::create_directory(path("plugins"));
  }
  // `obscura <arguments>` with OBSCURA_PLUGIN_DIR naming `plugin_dir`.
  test::CommandResult run_with_plugin_dir(const std::string& plugin_dir,
                                          const std::string& arguments) {
    return test::run_shell("OBSCURA_PLUGIN_DIR='" + plugin_dir + "' " +
                           test::cli_command_line(arguments));
  }
  std::string first_bytes(const std::string& file, size_t count) {
    std::ifstream in(file, std::ios::binary);
    std::string bytes(count, '\0');
    in.read(bytes.data(), std::streamsize(count));
    return bytes.substr(0, size_t(in.gcount()));
  }
  const std::string small_render = "render --width 8 --height 8 --spp 1 -o ";
};

// The dynamic loader's own account (LD_DEBUG=libs) of what `obscura --version` loads.
TEST_F(PluginLoadingCli, StartUpLoadsNeitherOpenImageIONorOpenMpi) {
  auto result = test::run_shell("LD_DEBUG=libs " + test::cli_command_line("--version"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ASSERT_THAT(result.output, HasSubstr("calling init")) << "LD_DEBUG=libs reported nothing";
  EXPECT_THAT(result.output, Not(HasSubstr("libOpenImageIO")));
  EXPECT_THAT(result.output, Not(HasSubstr("libmpi")));
  EXPECT_THAT(result.output, Not(HasSubstr("libobscura_image_codecs")));
}

// Writing and reading every format Obscura writes loads the native codecs, never OpenImageIO
// (issue 18: its ~250 libraries cost ~0.25 s); a Targa, which only OpenImageIO reads, loads it.
TEST_F(PluginLoadingCli, CommonFormatsLoadTheNativeCodecsNotOpenImageIO) {
  for (const char* ext : {"png", "exr", "jpg", "tif", "hdr"}) {
    auto result = test::run_shell(
        "LD_DEBUG=libs " + test::cli_command_line(small_render + path(std::string("o.") + ext)));
    ASSERT_EQ(result.exit_code, 0) << ext << ": " << result.output;
    EXPECT_THAT(result.output, HasSubstr("libobscura_image_codecs")) << ext;
    EXPECT_THAT(result.output, Not(HasSubstr("libOpenImageIO"))) << ext;
    EXPECT_THAT(result.output, Not(HasSubstr("libobscura_oiio_codecs"))) << ext;
  }
  // Reading them (and a PFM) back: `image diff` decodes both files.
  for (const char* ext : {"png", "exr", "jpg", "tif", "hdr"}) {
    std::string file = path(std::string("o.") + ext);
    auto diff = test::run_shell("LD_DEBUG=libs " +
                                test::cli_command_line("image diff " + file + " " + file));
    ASSERT_EQ(diff.exit_code, 0) << ext << ": " << diff.output;
    EXPECT_THAT(diff.output, Not(HasSubstr("libOpenImageIO"))) << ext;
  }
  ASSERT_EQ(test::run_shell(test::cli_command_line(small_render + path("o.pfm"))).exit_code, 0);
  auto pfm =
      test::run_shell("LD_DEBUG=libs " + test::cli_command_line("image convert " + path("o.pfm") +
                                                                " " + path("from-pfm.exr")));
  ASSERT_EQ(pfm.exit_code, 0) << pfm.output;
  EXPECT_THAT(pfm.output, Not(HasSubstr("libOpenImageIO")));
  // An uncompressed 2 × 1 true-colour Targa (TGA 2.0: an 18-byte header, then B, G, R).
  const unsigned char tga[] = {0, 0, 2, 0, 0,  0,    0,  0,  0,  0,  0,  0,
                               2, 0, 1, 0, 24, 0x20, 10, 20, 30, 40, 50, 60};
  std::ofstream(path("a.tga"), std::ios::binary)
      .write(reinterpret_cast<const char*>(tga), sizeof tga);
  auto targa =
      test::run_shell("LD_DEBUG=libs " +
                      test::cli_command_line("image diff " + path("a.tga") + " " + path("a.tga")));
  ASSERT_EQ(targa.exit_code, 0) << targa.output;
  EXPECT_THAT(targa.output, HasSubstr("libobscura_oiio_codecs"));
  EXPECT_THAT(targa.output, HasSubstr("libOpenImageIO"));
}

TEST_F(PluginLoadingCli, VersionRunsWithoutAnyPlugin) {
  auto result = run_with_plugin_dir(path("plugins"), "--version");
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST_F(PluginLoadingCli, AMissingCodecsPluginStopsARenderBeforeItsWorkAndSaysWhereItLooked) {
  auto result = run_with_plugin_dir(path("plugins"), small_render + path("out.png"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_THAT(result.output, HasSubstr(path("out.png")));
  EXPECT_THAT(result.output, HasSubstr(path("plugins") + "/libobscura_image_codecs.so: not there"));
  EXPECT_THAT(result.output, HasSubstr("OBSCURA_PLUGIN_DIR"));
  EXPECT_THAT(result.output, Not(HasSubstr("rendered"))) << "failed before rendering";
  EXPECT_FALSE(std::filesystem::exists(path("out.png")));
}

TEST_F(PluginLoadingCli, ABrokenPluginFileIsNamedWithWhyItDidNotLoad) {
  std::ofstream(path("plugins/libobscura_image_codecs.so")) << "not a shared object\n";
  auto result = run_with_plugin_dir(path("plugins"), small_render + path("out.exr"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_THAT(result.output,
              HasSubstr(path("plugins") + "/libobscura_image_codecs.so: cannot load"));
  EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
}

TEST_F(PluginLoadingCli, PfmIsWrittenWithoutTheCodecs) {
  auto result = run_with_plugin_dir(path("plugins"), small_render + path("out.pfm"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(first_bytes(path("out.pfm"), 3), "PF\n");  // the PFM signature, colour
}

TEST_F(PluginLoadingCli, TheOverrideFolderIsWhereThePluginIsTaken) {
  std::string build_dir = std::filesystem::path(test::cli_path()).parent_path().string();
  auto result = run_with_plugin_dir(build_dir, small_render + path("out.png"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(first_bytes(path("out.png"), 8), "\x89PNG\r\n\x1a\n");  // the PNG signature
}

}  // namespace
}  // namespace obscura

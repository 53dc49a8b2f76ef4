// `obscura render --shard I/N` and `obscura merge`: N independent processes each render a part of
// the frame to a partial film, and merging the parts, given in any order, writes the image (and
// auxiliary images) the lone render writes, bit for bit — as EXR pixels and as PNG bytes. Parts
// that do not belong together, missing or repeated parts and files that are not partial films
// are refused before anything is written. The reference is always the same render run whole.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "app/image_files.h"
#include "app/mpi_launcher.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;
using test::file_text;
using test::files_in;
using test::same_pixels;

// "out.exr" → "out.depth.exr".
std::string aov_file(const std::string& image, const std::string& aov) {
  return fs::path(image).replace_extension("." + aov + ".exr").string();
}

struct MergeCase {
  std::string name;
  std::string arguments;
  std::vector<std::string> aovs;  // empty: rendered without --aovs
};

std::vector<MergeCase> merge_cases() {
  const std::string tracer = "--renderer path --width 64 --height 48 --spp 4 --seed 3";
  // 3 × 2 of the rasterizer's 64-pixel tiles: with 5 parts, one part has two.
  const std::string raster = "--renderer raster --width 160 --height 120";
  // Finishing that needs the whole frame: each part carries its share and the recipe, and
  // merge finishes (render/frame_finish.h) — from the command line, and from the scene file's
  // render block (the night street asks for glare and flare itself).
  const std::string lens = "spheres-and-lights --lens double-gauss-50mm --width 64 --height 48";
  return {{"path", tracer, {}},
          {"path_aovs", tracer + " --aovs", {"albedo", "normal", "depth", "range", "id"}},
          {"raster", raster, {}},
          {"raster_aovs", raster + " --aovs", {"normal", "depth", "range", "id"}},
          {"path_flare_glare", lens + " --spp 2 --flare --glare", {}},
          {"raster_flare_glare", lens + " --renderer raster --flare --glare", {}},
          {"raster_post_dof", "depth-of-field --raster-dof post " + raster, {}},
          {"scene_file_glare_flare",
           test::source_path("scenes/night-street-flare.json") +
               " --width 96 --height 54 --spp 1 --renderer raster",
           {}}};
}

// gtest names a parameter in its messages by this, not by its bytes.
void PrintTo(const MergeCase& c, std::ostream* out) {
  *out << c.name;
}

class ShardMergeCli : public test::TempDirTest, public ::testing::WithParamInterface<MergeCase> {};

TEST_P(ShardMergeCli, MergedPartsAreTheLoneRenderBitForBit) {
  const MergeCase& c = GetParam();
  // The order the parts are merged in: never their own.
  const std::vector<std::vector<int>> orders = {{0}, {1, 0}, {3, 0, 4, 1, 2}};
  auto part_file = [&](int part, size_t parts) {
    return path("part" + std::to_string(part) + "of" + std::to_string(parts) + ".exr");
  };
  auto merged_file = [&](size_t parts, const std::string& extension) {
    return path("merged" + std::to_string(parts) + extension);
  };
  // Every render at once (they are independent, and mostly wait for the CLI to start), then
  // every merge.
  std::vector<std::string> renders = {
      test::cli_command_line("render " + c.arguments + " -q -o " + path("lone.exr")),
      test::cli_command_line("render " + c.arguments + " -q -o " + path("lone.png"))};
  std::vector<std::string> merges;
  for (const std::vector<int>& order : orders) {
    const std::string n = std::to_string(order.size());
    std::string parts;
    for (int i : order) {
      renders.push_back(test::cli_command_line("render " + c.arguments + " --shard " +
                                               std::to_string(i) + "/" + n + " -q -o " +
                                               part_file(i, order.size())));
      parts.append(" ").append(part_file(i, order.size()));
    }
    merges.push_back(
        test::cli_command_line("merge" + parts + " -o " + merged_file(order.size(), ".exr")));
    // The merged film is developed to PNG as the lone one is: checked once, for the most parts.
    if (order.size() == orders.back().size())
      merges.push_back(
          test::cli_command_line("merge" + parts + " -q -o " + merged_file(order.size(), ".png")));
  }
  for (const test::CommandResult& r : test::run_shells_concurrently(renders))
    ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const test::CommandResult& r : test::run_shells_concurrently(merges))
    ASSERT_EQ(r.exit_code, 0) << r.output;

  for (const std::vector<int>& order : orders) {
    SCOPED_TRACE(std::to_string(order.size()) + " parts");
    const std::string merged = merged_file(order.size(), ".exr");
    EXPECT_TRUE(same_pixels(merged, path("lone.exr")));
    EXPECT_EQ(test::image_attribute(merged, "obscura:partial"), "");
    for (const std::string& aov : c.aovs)
      EXPECT_TRUE(same_pixels(aov_file(merged, aov), path("lone." + aov + ".exr"))) << aov;
    if (c.aovs.empty()) {
      EXPECT_FALSE(fs::exists(aov_file(merged, "depth")));
    }
  }
  const std::string merged_png = merged_file(orders.back().size(), ".png");
  EXPECT_TRUE(file_text(merged_png) == file_text(path("lone.png")))
      << merged_png << " differs from the lone render's PNG";
}

INSTANTIATE_TEST_SUITE_P(Renders, ShardMergeCli, ::testing::ValuesIn(merge_cases()),
                         [](const auto& info) { return info.param.name; });

class ShardMergeCliErrors : public test::TempDirTest {
 protected:
  struct Refusal {
    std::string parts;
    std::vector<std::string> expected;  // what the message must say: the file, the part, why
  };
  // Runs `merge PARTS -o out.exr` for each refusal, all at once: each must fail saying what it
  // expects, and none may write anything.
  void expect_refused(const std::vector<Refusal>& refusals) {
    const std::vector<std::string> before = files_in(dir_);
    std::vector<std::string> commands;
    for (size_t i = 0; i < refusals.size(); ++i)
      commands.push_back(test::cli_command_line("merge " + refusals[i].parts + " -o " +
                                                path("out" + std::to_string(i) + ".exr")));
    const std::vector<test::CommandResult> results = test::run_shells_concurrently(commands);
    for (size_t i = 0; i < refusals.size(); ++i) {
      EXPECT_NE(results[i].exit_code, 0) << results[i].output;
      for (const std::string& text : refusals[i].expected)
        EXPECT_NE(results[i].output.find(text), std::string::npos) << "no '" << text << "' in\n"
                                                                   << results[i].output;
    }
    EXPECT_EQ(files_in(dir_), before);
  }

  // Renders `render --width 64 --height 48 --spp 2 ARGUMENTS` for each, all at once.
  void render(const std::vector<std::string>& arguments) {
    std::vector<std::string> commands;
    for (const std::string& a : arguments)
      commands.push_back(test::cli_command_line("render --width 64 --height 48 --spp 2 -q " + a));
    for (const test::CommandResult& r : test::run_shells_concurrently(commands))
      ASSERT_EQ(r.exit_code, 0) << r.output;
  }
};

// A copy of a partial film whose header `change` edits, the pixels kept as they are.
void rewrite_header(const std::string& from, const std::string& to,
                    const std::function<void(OIIO::ImageSpec&)>& change) {
  OIIO::ImageBuf image(from);
  ASSERT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << image.geterror();
  change(image.specmod());
  ASSERT_TRUE(image.write(to)) << image.geterror();
}

TEST_F(ShardMergeCliErrors, PartsThatDoNotMakeOneFrameAreRefusedNamingThePart) {
  const std::string p0 = path("p0.exr"), p1 = path("p1.exr");
  const std::string other_seed = path("seed9_p1.exr"), of_three = path("p0of3.exr");
  render({"--aovs --shard 0/2 -o " + p0, "--aovs --shard 1/2 -o " + p1,
          "--aovs --seed 9 --shard 1/2 -o " + other_seed, "--aovs --shard 0/3 -o " + of_three});
  // The parts are sound: merged, they make an image.
  auto r = test::run_cli("merge " + p1 + " " + p0 + " -q -o " + path("whole.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  fs::remove(path("whole.exr"));
  for (const char* aov : {"albedo", "normal", "depth", "range", "id"})
    fs::remove(aov_file(path("whole.exr"), aov));

  expect_refused({
      {p0, {"missing: 1"}},
      {p0 + " " + p1 + " " + p0, {p0, "part 0 is given twice"}},
      {p0 + " " + other_seed, {other_seed, "part 1", "other settings"}},
      {p0 + " " + p1 + " " + of_three, {of_three, "one of 3 parts, not 2"}},
  });
}

TEST_F(ShardMergeCliErrors, FilesThatAreNotPartialFilmsAreRefusedNamingTheFile) {
  const std::string p0 = path("p0.exr"), p1 = path("p1.exr"), with_aovs = path("with_aovs.exr");
  const std::string plain_exr = path("plain.exr"), plain_png = path("plain.png");
  render({"--shard 0/2 -o " + p0, "--shard 1/2 -o " + p1, "--aovs --shard 1/2 -o " + with_aovs,
          "-o " + plain_exr, "-o " + plain_png});

  // Headers edited after the part was written: a part that is not one, and parts without the
  // list of their auxiliary images (with none, or some, in their channels).
  const std::string bad_shard = path("bad_shard.exr"), no_aovs = path("no_aovs.exr");
  const std::string aovs_unlisted = path("aovs_unlisted.exr");
  rewrite_header(p1, bad_shard,
                 [](OIIO::ImageSpec& spec) { spec.attribute("obscura:shard", "7/2"); });
  rewrite_header(p1, no_aovs, [](OIIO::ImageSpec& spec) { spec.erase_attribute("obscura:aovs"); });
  rewrite_header(with_aovs, aovs_unlisted,
                 [](OIIO::ImageSpec& spec) { spec.erase_attribute("obscura:aovs"); });

  expect_refused({
      // A finished image is not a part, whatever its format.
      {p0 + " " + plain_exr, {plain_exr, "not a partial film"}},
      {p0 + " " + plain_png, {plain_png}},
      {p0 + " " + bad_shard, {bad_shard, "obscura:shard", "7/2"}},
      {p0 + " " + no_aovs, {no_aovs, "obscura:aovs"}},
      {p0 + " " + aovs_unlisted, {aovs_unlisted, "obscura:aovs"}},
  });
}

TEST_F(ShardMergeCliErrors, PartsWrittenBeforeTheRangeAovAreRefused) {
  // Their depth image was the distance along the ray, which is the range now: merging them would
  // write it as depth along the optical axis. (Parts kept as fuzz seeds, tracer and rasterizer.)
  for (const char* seed :
       {"part-0-of-1-aovs-before-range.exr", "raster-part-1-of-2-aovs-before-range.exr"}) {
    const std::string part = test::source_path(std::string("fuzz/corpus/shard/") + seed);
    expect_refused({{part, {part, "no range image", "older obscura"}}});
  }
}

TEST_F(ShardMergeCliErrors, ShardOptionsThatCannotWorkAreRefusedBeforeRendering) {
  const std::vector<test::Refusal> refusals = {
      {"--shard 0/2 -o " + path("part.png"), "OpenEXR"},
      {"--shard 3/2 -o " + path("part.exr"), "'3/2'"},
      {"--shard 2 -o " + path("part.exr"), "--shard"},
  };
  test::expect_refusals("render --width 64 --height 48 --spp 2 ", refusals);
  EXPECT_TRUE(files_in(dir_).empty());
}

class ShardUnderMpirun : public test::MpiCliTest {};

TEST_F(ShardUnderMpirun, IsRefusedBecauseTheRanksShareTheFrameAlready) {
  auto r = test::run_shell(mpirun_obscura(
      2, "render --width 64 --height 48 --spp 2 --shard 0/2 -o " + path("part.exr")));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("leave --shard out"), std::string::npos) << r.output;
  EXPECT_TRUE(files_in(dir_).empty()) << r.output;
}

}  // namespace
}  // namespace obscura

// `mpirun -np N obscura render`: the ranks split the frame's tiles, and rank 0 writes the image
// one process would have written, bit for bit, for any rank and thread count, with either
// renderer and every auxiliary image; a rank that fails, an output that cannot be written, a time
// limit and Ctrl-C end the whole job the way they end a lone render. The reference is always the
// same command run without mpirun. Skipped where the build has no MPI or mpirun cannot run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "app/image_files.h"
#include "app/mpi_launcher.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;
using test::files_in;
using test::image_attribute;
using test::same_pixels;

struct RendererCase {
  std::string name;
  std::string arguments;          // small enough for the whole matrix to take seconds
  std::vector<std::string> aovs;  // the auxiliary images --aovs writes beside the image
};

std::vector<RendererCase> renderer_cases() {
  const std::string tracer_frame = "--width 64 --height 48 --spp 4 --seed 3";
  const std::vector<std::string> tracer_aovs = {"albedo", "normal", "depth", "range", "id"};
  return {
      {"path", "--renderer path " + tracer_frame, tracer_aovs},
      {"whitted", "--renderer whitted " + tracer_frame, tracer_aovs},
      // The rasterizer's tiles are 64 pixels: 3 × 2 of them, the last column and row cut short.
      {"raster", "--renderer raster --width 160 --height 120", {"normal", "depth", "range", "id"}},
  };
}

// gtest names a parameter in its messages by this, not by its bytes.
void PrintTo(const RendererCase& c, std::ostream* out) {
  *out << c.name;
}

// "out.exr" → "out.depth.exr".
std::string aov_file(const std::string& image, const std::string& aov) {
  return fs::path(image).replace_extension("." + aov + ".exr").string();
}

struct Team {
  int ranks, threads;
};

class DistributedCliRenderer : public test::MpiCliTest,
                               public ::testing::WithParamInterface<RendererCase> {
 protected:
  // Renders `arguments` alone into lone.exr and with each team, all at once (the jobs mostly wait
  // for processes to start), and expects every image — and every auxiliary image in `aovs` — to
  // be the lone one's.
  void expect_every_team_renders_the_lone_image(const std::string& arguments,
                                                const std::vector<std::string>& aovs,
                                                const std::vector<Team>& teams) {
    const std::string lone = path("lone.exr");
    std::vector<std::string> commands = {
        test::cli_command_line("render " + arguments + " -q -o " + lone)};
    std::vector<std::string> outputs;
    for (const Team& team : teams) {
      const std::string threads = std::to_string(team.threads);
      outputs.push_back(path("np" + std::to_string(team.ranks) + "_t" + threads + ".exr"));
      commands.push_back(mpirun_obscura(team.ranks, "render " + arguments + " --threads " +
                                                        threads + " -q -o " + outputs.back()));
    }
    const std::vector<test::CommandResult> results = test::run_shells_concurrently(commands);
    ASSERT_EQ(results[0].exit_code, 0) << results[0].output;
    for (const std::string& aov : aovs) ASSERT_TRUE(fs::exists(aov_file(lone, aov))) << aov;
    for (size_t i = 0; i < teams.size(); ++i) {
      SCOPED_TRACE(std::to_string(teams[i].ranks) + " ranks, " + std::to_string(teams[i].threads) +
                   " threads");
      ASSERT_EQ(results[i + 1].exit_code, 0) << results[i + 1].output;
      EXPECT_TRUE(same_pixels(outputs[i], lone));
      EXPECT_EQ(image_attribute(outputs[i], "obscura:partial"), "");
      for (const std::string& aov : aovs)
        EXPECT_TRUE(same_pixels(aov_file(outputs[i], aov), aov_file(lone, aov))) << aov;
    }
  }
};

const std::vector<Team> kEveryTeam = {{1, 1}, {1, 2}, {2, 1}, {2, 2}, {3, 1}, {3, 2}};

TEST_P(DistributedCliRenderer, EveryRankAndThreadCountRendersTheLoneImage) {
  expect_every_team_renders_the_lone_image(GetParam().arguments, {}, kEveryTeam);
}

TEST_P(DistributedCliRenderer, EveryRankAndThreadCountRendersTheLoneAuxiliaryImages) {
  expect_every_team_renders_the_lone_image(GetParam().arguments + " --aovs", GetParam().aovs,
                                           kEveryTeam);
}

INSTANTIATE_TEST_SUITE_P(Renderers, DistributedCliRenderer, ::testing::ValuesIn(renderer_cases()),
                         [](const auto& info) { return info.param.name; });

std::string depth_of_field_arguments() {
  return "render " + test::quoted(test::source_path("scenes/depth-of-field.json")) +
         " --renderer raster --width 160 --height 120 --raster-samples 6 --seed 2 --aovs -q";
}

class DistributedCli : public test::MpiCliTest {
 protected:
  // The depth-of-field scene rendered alone and on each number of ranks, all at once.
  void expect_depth_of_field_on_ranks_is_the_lone_image(const std::string& dof,
                                                        const std::vector<int>& rank_counts) {
    const std::string arguments = depth_of_field_arguments() + " --raster-dof " + dof + " -o ";
    const std::string lone = path("lone.exr");
    std::vector<std::string> commands = {test::cli_command_line(arguments + lone)};
    for (int ranks : rank_counts)
      commands.push_back(
          mpirun_obscura(ranks, arguments + path("np" + std::to_string(ranks) + ".exr")));
    const std::vector<test::CommandResult> results = test::run_shells_concurrently(commands);
    ASSERT_EQ(results[0].exit_code, 0) << results[0].output;
    for (size_t i = 0; i < rank_counts.size(); ++i) {
      const std::string ranks = std::to_string(rank_counts[i]);
      SCOPED_TRACE(ranks + " ranks");
      ASSERT_EQ(results[i + 1].exit_code, 0) << results[i + 1].output;
      const std::string out = path("np" + ranks + ".exr");
      EXPECT_TRUE(same_pixels(out, lone));
      for (const std::string aov : {"normal", "depth", "range", "id"})
        EXPECT_TRUE(same_pixels(aov_file(out, aov), aov_file(lone, aov))) << aov;
    }
  }
};

TEST_F(DistributedCli, AccumulatedDepthOfFieldIsTheLoneImage) {
  expect_depth_of_field_on_ranks_is_the_lone_image("accumulate", {2, 3});
}

TEST_F(DistributedCli, PostProcessDepthOfFieldBlursTheAssembledFrameAsTheLoneOne) {
  // The blur needs the whole frame's colour and depth: rank 0 applies it after assembling them.
  expect_depth_of_field_on_ranks_is_the_lone_image("post", {2, 3});
}

TEST_F(DistributedCli, ARankThatCannotReadTheSceneFailsTheJobAndNamesItself) {
  // MPMD: rank 0 gets a scene that exists, rank 1 one that does not.
  const std::string frame = " --width 64 --height 48 --spp 4 -q -o " + path("out.exr");
  const std::string scene = test::quoted(test::source_path("scenes/depth-of-field.json"));
  const std::string missing = path("missing.json");
  auto r = test::run_shell(mpirun() + " -np 1 " + test::quoted(test::cli_path()) + " render " +
                           scene + frame + " : -np 1 " + test::quoted(test::cli_path()) +
                           " render " + missing + frame);
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rank 1: " + missing), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("rank 0:"), std::string::npos) << "rank 0 was fine\n" << r.output;
  EXPECT_TRUE(files_in(dir_).empty()) << r.output;
}

TEST_F(DistributedCli, AnOutputThatCannotBeWrittenFailsBeforeRendering) {
  const std::string out = path("no-such-directory/out.exr");
  auto r =
      test::run_shell(mpirun_obscura(2, "render --width 64 --height 48 --spp 100000 -q -o " + out));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no-such-directory"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  // Checked before rendering: 100000 samples per pixel would have taken minutes.
  EXPECT_EQ(r.output.find("rendered"), std::string::npos) << r.output;
  EXPECT_TRUE(files_in(dir_).empty()) << r.output;
}

TEST_F(DistributedCli, ATimeLimitStopsEveryRankAfterTheSamePass) {
  const std::string out = path("t.exr");
  auto r = test::run_shell(mpirun_obscura(
      2, "render --width 32 --height 24 --spp 1000000 --time-limit 1 --threads 1 -o " + out));
  EXPECT_NE(r.exit_code, 0) << r.output;  // 3 from obscura, passed on (or not) by mpirun
  EXPECT_NE(r.output.find("[partial: time limit, "), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(out)) << r.output;
  EXPECT_EQ(image_attribute(out, "obscura:partial"), "time limit");
  // Both ranks stopped after the same pass: the image is a lone render of that many samples.
  const std::string description = image_attribute(out, "ImageDescription");
  const size_t of = description.find(" of 1000000 samples per pixel");
  ASSERT_NE(of, std::string::npos) << description;
  const size_t number = description.find_last_of(' ', of - 1) + 1;
  const std::string spp = description.substr(number, of - number);
  r = test::run_cli("render --width 32 --height 24 --spp " + spp + " -q -o " + path("lone.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(same_pixels(out, path("lone.exr"))) << spp << " samples per pixel";
}

// `job` started in the background, then Ctrl-C to it once `ranks` of its children catch SIGINT
// (a rank installs its handler just before it renders; /proc shows the signals a process
// catches): a fixed delay would be too short where the machine is busy starting other processes.
std::string interrupted_while_rendering(const std::string& job, int ranks) {
  return job +
         " 2>&1 & job=$!; "
         "for attempt in $(seq 300); do "
         "  catching=$(cat /proc/[0-9]*/status 2>/dev/null | awk -v job=$job '"
         "    $1 == \"Name:\" { child = 0 } $1 == \"PPid:\" && $2 == job { child = 1 }"
         "    $1 == \"SigCgt:\" && child && index(\"2367abef\", substr($2, length($2))) { n++ }"
         "    END { print n + 0 }'); "
         "  [ \"$catching\" -ge " +
         std::to_string(ranks) +
         " ] && break; sleep 0.1; "
         "done; sleep 0.5; kill -INT $job; wait $job";
}

TEST_F(DistributedCli, CtrlCToMpirunWritesThePartialImageMarkedInterrupted) {
  const std::string out = path("i.exr");
  auto r = test::run_shell(interrupted_while_rendering(
      mpirun_obscura(2, "render --width 64 --height 48 --spp 100000 --aovs -o " + out), 2));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("[partial: interrupted, "), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(out)) << r.output;
  EXPECT_EQ(image_attribute(out, "obscura:partial"), "interrupted");
  EXPECT_EQ(image_attribute(aov_file(out, "depth"), "obscura:partial"), "interrupted");
  // Every rank's tiles arrived. A lone render of one sample per pixel drew the first sample of
  // each pixel the interrupted one drew: wherever that sample hit something, the interrupted
  // render's id is the same, which a pixel that never arrived from its rank would not have.
  r = test::run_cli("render --width 64 --height 48 --spp 1 --aovs -q -o " + path("lone.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image ids = read_image(aov_file(out, "id")), lone_ids = read_image(path("lone.id.exr"));
  const Image depth = read_image(aov_file(out, "depth"));
  int hits = 0;
  for (int y = 0; y < ids.height; ++y)
    for (int x = 0; x < ids.width; ++x)
      if (lone_ids.at(x, y, 0) >= 0) {
        ++hits;
        ASSERT_EQ(ids.at(x, y, 0), lone_ids.at(x, y, 0)) << x << "," << y;
        ASSERT_TRUE(std::isfinite(depth.at(x, y, 0))) << x << "," << y;
      }
  EXPECT_GT(hits, ids.width * ids.height / 2);
}

// A CLI built without MPI that mpirun starts anyway says so and renders nothing, instead of N
// processes each rendering the whole frame over one another's output. Open MPI's launcher tells
// its processes the job's size in OMPI_COMM_WORLD_SIZE, which is all such a build can see, so the
// launch is imitated with that variable (a real mpirun needs an MPI build to be installed).
TEST(DistributedCliWithoutMpi, StartedAsOneOfSeveralRanksSaysItWasBuiltWithoutMpi) {
#ifdef OBSCURA_MPIEXEC
  GTEST_SKIP() << "this build has MPI; the message is for builds without it";
#else
  const std::string dir = test::make_temp_dir("no-mpi");
  const std::string out = (fs::path(dir) / "out.png").string();
  auto r = test::run_shell("OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 " +
                           test::cli_command_line("render --width 8 --height 8 -o " + out));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("built without MPI"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  // Rank 1 stays silent: one message for the job.
  r = test::run_shell("OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=1 " +
                      test::cli_command_line("render --width 8 --height 8 -o " + out));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output, "");
  // One rank is no team: it renders as a lone process.
  r = test::run_shell("OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0 " +
                      test::cli_command_line("render --width 8 --height 8 -q -o " + out));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out));
  fs::remove_all(dir);
#endif
}

}  // namespace
}  // namespace obscura

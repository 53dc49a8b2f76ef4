// Outputs are written whole or not at all (obscura/io/atomic_file.h): a failing write — here a
// file-size limit, which fails like a full disk — is reported, leaves no temporary file and
// never replaces an existing output; a replaced output keeps its permission bits.
#include "obscura/io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/mesh_test_files.h"
#include "obscura/io/image_io.h"
#include "obscura/math/error.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

unsigned mode_of(const std::string& path) {
  struct stat s;
  return ::stat(path.c_str(), &s) == 0 ? unsigned(s.st_mode & 07777) : 0u;
}

class AtomicOutput : public test::TempDirTest {
 protected:
  // Names in the directory other than the given ones (temporary files left behind).
  std::vector<std::string> others(std::initializer_list<std::string> expected) const {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      std::string name = entry.path().filename().string();
      if (std::find(expected.begin(), expected.end(), name) == expected.end())
        found.push_back(name);
    }
    return found;
  }
  // A linear image whose every encoding is far above the 1 KiB size limit used below: noise
  // does not compress.
  std::string noise_input() {
    Image image(128, 128, 3);
    uint32_t state = 12345;
    for (float& v : image.data) {
      state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
      v = float(state >> 8) / float(1 << 24);
    }
    write_image(path("in.exr"), image);
    return path("in.exr");
  }
};

TEST_F(AtomicOutput, UncommittedFileLeavesNothingAndCommitReplaces) {
  std::string target = path("a.bin");
  {
    AtomicFile file(target);
    file.write(std::string("half"));
    EXPECT_TRUE(fs::exists(file.temporary()));
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_TRUE(others({}).empty());
  write_file_atomically(target, std::vector<uint8_t>{'o', 'l', 'd'});
  write_file_atomically(target, std::vector<uint8_t>{'n', 'e', 'w', '!'});
  EXPECT_EQ(test::read_file(target), "new!");
  EXPECT_TRUE(others({"a.bin"}).empty());
}

TEST_F(AtomicOutput, CannotCreateInMissingDirectoryNamesTheTarget) {
  try {
    write_file_atomically(path("missing/a.bin"), std::vector<uint8_t>{1});
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/a.bin"), std::string::npos) << e.what();
  }
}

TEST_F(AtomicOutput, ReplacedFileKeepsItsPermissionBits) {
  Image image(4, 4, 3);
  for (unsigned mode : {0600u, 0640u, 0755u, 0444u | 0200u}) {
    for (const char* name : {"keep.png", "keep.pfm", "keep.y4m"}) {
      write_image(path(name), image);
      ASSERT_EQ(::chmod(path(name).c_str(), mode), 0);
      write_image(path(name), image);
      EXPECT_EQ(mode_of(path(name)), mode) << name;
    }
  }
  // A new file gets the usual 0666 less the umask.
  mode_t mask = ::umask(0);
  ::umask(mask);
  write_image(path("new.exr"), image);
  EXPECT_EQ(mode_of(path("new.exr")), 0666u & ~unsigned(mask));
}

// `ulimit -f 1` makes any write past the first 512 or 1024 bytes fail with EFBIG (the CLI ignores
// SIGXFSZ), the way a full disk fails: each format must report it and keep the old output.
TEST_F(AtomicOutput, FailedWriteKeepsExistingOutputForEveryFormat) {
  std::string input = noise_input();
  for (const char* ext : {".png", ".exr", ".hdr", ".pfm", ".jpg", ".tif", ".y4m"}) {
    std::string name = std::string("out") + ext;
    std::string out = path(name);
    std::string good = "the user's good file";
    std::ofstream(out, std::ios::binary) << good;
    ASSERT_EQ(::chmod(out.c_str(), 0640), 0);
    // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"'" + std::string`.)
    std::string convert(1, '\'');
    convert.append(test::cli_path()).append("' image convert ").append(input + " " + out);
    auto r = test::run_shell(convert);
    ASSERT_EQ(r.exit_code, 0) << r.output;  // without a limit the write succeeds...
    EXPECT_GT(fs::file_size(out), 2048u) << name;
    EXPECT_EQ(mode_of(out), 0640u) << name;
    std::ofstream(out, std::ios::binary | std::ios::trunc) << good;
    unsigned mode = mode_of(out);
    r = test::run_shell("ulimit -f 1; " + convert);  // ...and under the limit it fails, whole
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.output;
    EXPECT_NE(r.output.find("obscura: error: " + out + ": "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
    EXPECT_EQ(test::read_file(out), good) << name;
    EXPECT_EQ(mode_of(out), mode) << name;
    EXPECT_EQ(mode_of(out), 0640u) << name;
    EXPECT_TRUE(others({"in.exr", name}).empty()) << name << ": " << others({"in.exr", name})[0];
    fs::remove(out);
  }
}

}  // namespace
}  // namespace obscura

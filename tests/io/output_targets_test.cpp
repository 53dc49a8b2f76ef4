// What an output may replace (obscura/io/atomic_file.h): a regular file or a new name, never a
// device, a FIFO or a symbolic link to one; and outputs committed together through an
// OutputTransaction are replaced all or none.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/mesh_test_files.h"
#include "obscura/io/atomic_file.h"
#include "obscura/io/image_io.h"
#include "obscura/math/request_error.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

class OutputTargets : public test::TempDirTest {
 protected:
  // The names in the directory.
  std::vector<std::string> names() const {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(dir_))
      found.push_back(entry.path().filename().string());
    std::sort(found.begin(), found.end());
    return found;
  }
};

// The error's message for writing to `target`, or "" when it was written.
std::string refusal_for(const std::string& target) {
  try {
    write_file_atomically(target, std::vector<uint8_t>{'x'});
  } catch (const RequestError& e) {
    return e.what();
  }
  return "";
}

TEST_F(OutputTargets, DevicesFifosAndLinksToThemAreRefusedAndLeftAsTheyWere) {
  ASSERT_EQ(::mkfifo(path("pipe.png").c_str(), 0600), 0);
  fs::create_symlink("/dev/null", path("null.png"));
  fs::create_symlink(path("pipe.png"), path("to_pipe.png"));
  EXPECT_NE(refusal_for(path("pipe.png")).find("a FIFO"), std::string::npos);
  EXPECT_NE(refusal_for("/dev/null").find("/dev/null: is a character device"), std::string::npos);
  EXPECT_NE(refusal_for(path("null.png")).find("through a symbolic link) a character device"),
            std::string::npos);
  EXPECT_NE(refusal_for(path("to_pipe.png")).find("a FIFO"), std::string::npos);
  EXPECT_TRUE(fs::is_fifo(path("pipe.png")));
  EXPECT_TRUE(fs::is_symlink(path("null.png")));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_EQ(names(), (std::vector<std::string>{"null.png", "pipe.png", "to_pipe.png"}));
  // The image writers check it before encoding, naming the option when given one.
  try {
    check_output_path(path("pipe.png"), "--output");
    ADD_FAILURE();
  } catch (const RequestError& e) {
    EXPECT_NE(std::string(e.what()).find("--output " + path("pipe.png") + ": is a FIFO"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(write_image(path("to_pipe.png"), Image(2, 2, 3)), RequestError);
  EXPECT_TRUE(fs::is_fifo(path("pipe.png")));
}

TEST_F(OutputTargets, RegularFilesAndLinksToThemAreStillReplaced) {
  write_file_atomically(path("a.bin"), std::vector<uint8_t>{'o', 'l', 'd'});
  EXPECT_EQ(refusal_for(path("a.bin")), "");
  EXPECT_EQ(test::read_file(path("a.bin")), "x");
  EXPECT_EQ(refusal_for(path("new.bin")), "");
}

TEST_F(OutputTargets, TransactionReplacesAllOrNone) {
  write_file_atomically(path("frame.bin"), std::vector<uint8_t>{'o', 'l', 'd'});
  {
    OutputTransaction outputs;
    write_file_atomically(path("frame.bin"), std::vector<uint8_t>{'n', 'e', 'w'});
    write_file_atomically(path("truth.bin"), std::vector<uint8_t>{'t'});
    EXPECT_EQ(test::read_file(path("frame.bin")), "old");  // not yet replaced
    EXPECT_FALSE(fs::exists(path("truth.bin")));
  }  // abandoned (an error, a cancel): nothing replaced, no temporary left
  EXPECT_EQ(test::read_file(path("frame.bin")), "old");
  EXPECT_EQ(names(), std::vector<std::string>{"frame.bin"});
  {
    OutputTransaction outputs;
    write_file_atomically(path("frame.bin"), std::vector<uint8_t>{'n', 'e', 'w'});
    write_file_atomically(path("truth.bin"), std::vector<uint8_t>{'t'});
    outputs.commit();
  }
  EXPECT_EQ(test::read_file(path("frame.bin")), "new");
  EXPECT_EQ(test::read_file(path("truth.bin")), "t");
  EXPECT_EQ(names(), (std::vector<std::string>{"frame.bin", "truth.bin"}));
  // After the transaction, files are committed one by one again.
  write_file_atomically(path("later.bin"), std::vector<uint8_t>{'l'});
  EXPECT_TRUE(fs::exists(path("later.bin")));
}

}  // namespace
}  // namespace obscura

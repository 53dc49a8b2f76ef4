// The cache folder for tables fitted at run time: what is written reads back bit for bit; an
// entry of another size, a damaged one, a FIFO in its place or a name that would leave the
// folder is a miss (never a hang or a wrong table); OBSCURA_CACHE_DIR=off turns it off.
#include "obscura/math/disk_cache.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace obscura {
namespace {

namespace fs = std::filesystem;

// Points OBSCURA_CACHE_DIR at a fresh folder for the test, and back where it was after.
class CacheFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const char* old = std::getenv("OBSCURA_CACHE_DIR")) saved_ = old;
    folder_ = fs::temp_directory_path() / ("obscura-disk-cache-test-" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    ::setenv("OBSCURA_CACHE_DIR", folder_.c_str(), 1);
  }
  void TearDown() override {
    if (saved_)
      ::setenv("OBSCURA_CACHE_DIR", saved_->c_str(), 1);
    else
      ::unsetenv("OBSCURA_CACHE_DIR");
    fs::remove_all(folder_);
  }
  static std::vector<std::byte> bytes(size_t n) {
    std::vector<std::byte> b(n);
    for (size_t i = 0; i < n; ++i) b[i] = std::byte((i * 131 + 7) & 0xff);
    return b;
  }
  fs::path folder_;
  std::optional<std::string> saved_;
};

TEST_F(CacheFolder, WhatIsWrittenReadsBackBitForBit) {
  const std::vector<std::byte> table = bytes(100'000);
  ASSERT_TRUE(write_cached_table("table-1.bin", table));
  std::optional<std::vector<std::byte>> back = read_cached_table("table-1.bin", table.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, table);
  // Nothing else is left in the folder (the temporary file was renamed into place).
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

TEST_F(CacheFolder, AnEntryOfAnotherSizeOrDamagedIsAMiss) {
  const std::vector<std::byte> table = bytes(4096);
  ASSERT_TRUE(write_cached_table("t.bin", table));
  EXPECT_FALSE(read_cached_table("t.bin", 4095));
  EXPECT_FALSE(read_cached_table("t.bin", 4097));
  EXPECT_FALSE(read_cached_table("missing.bin", 4096));
  {  // one byte changed in place
    std::fstream f(folder_ / "t.bin", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(1000);
    f.put(char(0x5a ^ char(table[1000])));
  }
  EXPECT_FALSE(read_cached_table("t.bin", 4096));
  fs::resize_file(folder_ / "t.bin", 2000);  // truncated
  EXPECT_FALSE(read_cached_table("t.bin", 4096));
}

TEST_F(CacheFolder, AFifoInPlaceOfAnEntryIsAMissNotAHang) {
  fs::create_directories(folder_);
  ASSERT_EQ(::mkfifo((folder_ / "fifo.bin").c_str(), 0600), 0);
  EXPECT_FALSE(read_cached_table("fifo.bin", 16));
}

TEST_F(CacheFolder, NamesThatWouldLeaveTheFolderAreRefused) {
  const std::vector<std::byte> table = bytes(16);
  for (const char* name : {"../escape.bin", "a/b.bin", "", ".hidden", "/abs.bin"}) {
    EXPECT_FALSE(write_cached_table(name, table)) << name;
    EXPECT_FALSE(read_cached_table(name, 16)) << name;
  }
  EXPECT_FALSE(fs::exists(folder_.parent_path() / "escape.bin"));
}

TEST_F(CacheFolder, OffTurnsItOff) {
  ::setenv("OBSCURA_CACHE_DIR", "off", 1);
  EXPECT_FALSE(write_cached_table("t.bin", bytes(16)));
  EXPECT_FALSE(read_cached_table("t.bin", 16));
  EXPECT_FALSE(fs::exists("off"));
}

}  // namespace
}  // namespace obscura

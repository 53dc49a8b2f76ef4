// The OpenEXR header walk against headers laid out by hand from the OpenEXR file-layout document:
// magic, version, then attributes (name, type, 4-byte little-endian size, value), an empty name
// ending the header.
#include "obscura/io/exr_header_check.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "obscura/io/image_io.h"
#include "obscura/math/error.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

class ExrHeader {
 public:
  ExrHeader() { bytes_ = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0}; }
  // An attribute whose declared size is the value's length unless `declared` says otherwise.
  ExrHeader& add(const std::string& name, const std::string& type,
                 const std::vector<uint8_t>& value, int64_t declared = -1) {
    put_name(name);
    put_name(type);
    put_u32(uint32_t(declared < 0 ? int64_t(value.size()) : declared));
    bytes_.insert(bytes_.end(), value.begin(), value.end());
    return *this;
  }
  std::vector<uint8_t> finish() const {
    std::vector<uint8_t> out = bytes_;
    out.push_back(0);                // end of header
    out.resize(out.size() + 64, 0);  // stand-in for the offset table and pixels
    return out;
  }

 private:
  void put_name(const std::string& s) {
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
  }
  void put_u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes_.push_back(uint8_t(v >> (8 * i)));
  }
  std::vector<uint8_t> bytes_;
};

std::vector<uint8_t> u32s(std::initializer_list<uint32_t> values) {
  std::vector<uint8_t> out;
  for (uint32_t v : values)
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
  return out;
}

// One channel "R", half (type 1), sampling 1 × 1: name, type, pLinear + 3 reserved, xs, ys; then
// the empty name that ends the list.
std::vector<uint8_t> one_channel_list() {
  std::vector<uint8_t> v = {'R', 0};
  std::vector<uint8_t> rest = u32s({1, 0, 1, 1});
  v.insert(v.end(), rest.begin(), rest.end());
  v.push_back(0);
  return v;
}

// Runs the check; returns "" when it passes, the message otherwise.
std::string check(const std::vector<uint8_t>& file) {
  auto read = [&file](uint64_t offset, size_t size, uint8_t* out) {
    if (offset > file.size() || size > file.size() - offset) return false;
    std::memcpy(out, file.data() + offset, size);
    return true;
  };
  try {
    check_exr_header(read, file.size(), "test.exr");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

ExrHeader minimal() {
  ExrHeader h;
  h.add("channels", "chlist", one_channel_list())
      .add("compression", "compression", {0})
      .add("dataWindow", "box2i", u32s({0, 0, 3, 3}))
      .add("lineOrder", "lineOrder", {0});
  return h;
}

TEST(ExrHeaderCheck, AWellFormedHeaderPasses) {
  EXPECT_EQ(check(minimal().finish()), "");
  ExrHeader h = minimal();
  h.add("preview", "preview", [] {
    std::vector<uint8_t> v = u32s({2, 3});
    v.resize(8 + 2 * 3 * 4, 7);
    return v;
  }());
  h.add("notes", "stringvector", [] {
    std::vector<uint8_t> v = u32s({2});
    v.push_back('h');
    v.push_back('i');
    std::vector<uint8_t> empty = u32s({0});
    v.insert(v.end(), empty.begin(), empty.end());
    return v;
  }());
  h.add("owner", "string", {'m', 'e'}).add("custom", "someUnknownType", {1, 2, 3});
  EXPECT_EQ(check(h.finish()), "");
}

// OpenEXR reads a box2i as 16 bytes whatever its declared size: a declared 13 left it reading
// the next attribute 3 bytes late (the fuzz finding: 1.7 GB claimed by a 407-byte file).
TEST(ExrHeaderCheck, AFixedSizeValueMustDeclareItsSize) {
  ExrHeader h;
  h.add("dataWindow", "box2i", u32s({0, 0, 3, 3}), 13);
  EXPECT_NE(check(h.finish()).find("'dataWindow' (box2i): declares 13 bytes; a box2i holds 16"),
            std::string::npos);
  ExrHeader f;
  f.add("pixelAspectRatio", "float", {0, 0, 0x80, 0x3f, 0}, 5);
  EXPECT_NE(check(f.finish()).find("a float holds 4"), std::string::npos);
  ExrHeader m;
  m.add("worldToCamera", "m44f", std::vector<uint8_t>(60, 0));
  EXPECT_NE(check(m.finish()).find("a m44f holds 64"), std::string::npos);
}

TEST(ExrHeaderCheck, AChannelListMustEndWhereItsSizeSays) {
  std::vector<uint8_t> list = one_channel_list();
  ExrHeader longer;  // the list's terminator lies beyond the declared size
  longer.add("channels", "chlist", list, int64_t(list.size()) - 1);
  EXPECT_NE(check(longer.finish()).find("runs past"), std::string::npos);
  ExrHeader shorter;  // declared size has bytes after the terminator
  std::vector<uint8_t> padded = list;
  padded.push_back(0);
  shorter.add("channels", "chlist", padded);
  EXPECT_NE(check(shorter.finish()).find("ends before"), std::string::npos);
}

TEST(ExrHeaderCheck, APreviewMustFillItsSize) {
  ExrHeader h;  // 65535 × 65535 RGBA claimed in 16 bytes
  std::vector<uint8_t> v = u32s({65535, 65535});
  v.resize(16, 0);
  h.add("preview", "preview", v);
  EXPECT_NE(check(h.finish()).find("65535 × 65535 RGBA pixels does not fill its 16 bytes"),
            std::string::npos);
  ExrHeader overflow;  // sides whose product × 4 overflows 64 bits cannot pass by wrapping
  std::vector<uint8_t> w = u32s({0xffffffffu, 0xffffffffu});
  w.resize(12, 0);
  overflow.add("preview", "preview", w);
  EXPECT_NE(check(overflow.finish()).find("does not fill"), std::string::npos);
}

TEST(ExrHeaderCheck, AStringVectorStringMustFitInTheAttribute) {
  ExrHeader h;
  std::vector<uint8_t> v = u32s({0x7fffffff});  // a 2 GB string in a 6-byte value
  v.push_back('x');
  v.push_back('y');
  h.add("notes", "stringvector", v);
  EXPECT_NE(check(h.finish()).find("'notes' (stringvector): a string runs past"),
            std::string::npos);
}

// Every EXR Obscura writes, and the fuzz finding as a file, through the whole reader.
TEST(ExrHeaderCheck, RealFilesPassAndTheFuzzFindingIsRefused) {
  std::string dir = test::make_temp_dir("obscura-exr-header");
  Image image(4, 2, 4);
  image.data.assign(image.data.size(), 0.5f);
  write_image(dir + "/ok.exr", image);
  EXPECT_EQ(read_image(dir + "/ok.exr").width, 4);
  std::string regress = test::source_path("fuzz/corpus/image/regress-exr-box2i-of-13-bytes.exr");
  try {
    read_image(regress);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("declares 13 bytes; a box2i holds 16"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace obscura

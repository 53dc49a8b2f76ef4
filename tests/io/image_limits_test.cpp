// The decoded-size limit (obscura/io/image_limits.h): a file that declares more pixels than the
// limit is refused from its header, before any pixel memory is allocated.
#include "obscura/io/image_limits.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "obscura/io/gltf_loader.h"
#include "obscura/io/image_io.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"
#include "png_bytes.h"
#include "run_command.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

using test::put_chunk;
using test::put_u32;

// A well-formed PNG signature and IHDR (8-bit RGB) declaring width × height, followed by a tiny
// IDAT that holds far fewer pixels than declared: a 60-byte file claiming gigabytes.
std::vector<uint8_t> png_declaring(uint32_t width, uint32_t height) {
  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<uint8_t> ihdr;
  put_u32(ihdr, width);
  put_u32(ihdr, height);
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // depth 8, colour type RGB, deflate, no interlace
  put_chunk(png, "IHDR", ihdr);
  put_chunk(png, "IDAT", {0x78, 0x9C, 0x63, 0x00, 0x00, 0x00, 0x01, 0x00, 0x01});
  put_chunk(png, "IEND", {});
  return png;
}

// RFC 4648 base64, for a glTF data URI.
std::string base64(const std::vector<uint8_t>& bytes) {
  const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= bytes[i + 2];
    size_t left = bytes.size() - i;  // 1, 2 or 3 bytes in this group
    for (size_t k = 0; k < 4; ++k) out += k <= left ? alphabet[(n >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

class ImageLimits : public test::TempDirTest {
 protected:
  void TearDown() override {
    set_max_image_pixels(std::nullopt);
    unsetenv("OBSCURA_MAX_IMAGE_PIXELS");
    TempDirTest::TearDown();
  }
  std::string write_file(const std::string& name, const std::vector<uint8_t>& bytes) {
    std::string p = path(name);
    std::ofstream(p, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return p;
  }
  std::string small_png(const std::string& name, int w, int h) {
    Image image(w, h, 3);
    write_image(path(name), image);
    return path(name);
  }
};

// The message a refused 20000 × 20000 image gives: the file, its size, the limit, the way out.
void expect_limit_message(const std::string& message, const std::string& file) {
  EXPECT_NE(message.find(file), std::string::npos) << message;
  EXPECT_NE(message.find("20000x20000"), std::string::npos) << message;
  EXPECT_NE(message.find("67108864"), std::string::npos) << message;  // 8192², the default
  EXPECT_NE(message.find("--max-image-pixels"), std::string::npos) << message;
  EXPECT_NE(message.find("OBSCURA_MAX_IMAGE_PIXELS"), std::string::npos) << message;
}

TEST_F(ImageLimits, DefaultIs8192Squared) {
  EXPECT_EQ(kDefaultMaxImagePixels, 67108864u);
  EXPECT_EQ(max_image_pixels(), 67108864u);
}

TEST_F(ImageLimits, HugeDeclaredPngIsRefusedFromItsHeaderByEveryReader) {
  std::vector<uint8_t> bytes = png_declaring(20000, 20000);
  std::string file = write_file("huge.png", bytes);
  auto start = std::chrono::steady_clock::now();
  try {
    read_image(file);
    ADD_FAILURE() << "read_image accepted a 20000x20000 image";
  } catch (const Error& e) {
    expect_limit_message(e.what(), file);
  }
  try {
    read_texture(file, TextureEncoding::kSrgb);
    ADD_FAILURE() << "read_texture accepted a 20000x20000 image";
  } catch (const Error& e) {
    expect_limit_message(e.what(), file);
  }
  try {
    decode_texture(bytes, "model.gltf: images[0]", "image/png", TextureEncoding::kSrgb);
    ADD_FAILURE() << "decode_texture accepted a 20000x20000 image";
  } catch (const Error& e) {
    expect_limit_message(e.what(), "model.gltf: images[0]");
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST_F(ImageLimits, HugeGltfImageIsNamedInAWarningWithTheLimit) {
  std::string gltf = R"({"asset": {"version": "2.0"}, "images": [{"uri": "data:image/png;base64,)" +
                     base64(png_declaring(20000, 20000)) + R"("}]})";
  Scene scene = load_gltf_bytes(
      std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(gltf.data()), gltf.size()),
      "huge.gltf", dir_);
  ASSERT_EQ(scene.warnings.size(), 1u);
  expect_limit_message(scene.warnings[0], "huge.gltf: images[0]");
}

TEST_F(ImageLimits, EnvironmentVariableAndSetterMoveTheLimit) {
  std::string file = small_png("64.png", 64, 64);  // 4096 pixels
  EXPECT_EQ(read_image(file).width, 64);
  setenv("OBSCURA_MAX_IMAGE_PIXELS", "4095", 1);
  EXPECT_EQ(max_image_pixels(), 4095u);
  EXPECT_THROW(read_image(file), Error);
  setenv("OBSCURA_MAX_IMAGE_PIXELS", "4096", 1);
  EXPECT_EQ(read_texture(file, TextureEncoding::kSrgb).width, 64);
  set_max_image_pixels(100);  // the setter (the CLI option) wins over the variable
  EXPECT_THROW(read_texture(file, TextureEncoding::kSrgb), Error);
  set_max_image_pixels(std::nullopt);
  EXPECT_EQ(max_image_pixels(), 4096u);
  EXPECT_THROW(set_max_image_pixels(0), Error);
}

TEST_F(ImageLimits, MalformedEnvironmentVariableIsNamed) {
  for (const char* bad : {"abc", "-5", "0", "12x", "1e9", "99999999999999999999999"}) {
    setenv("OBSCURA_MAX_IMAGE_PIXELS", bad, 1);
    try {
      max_image_pixels();
      ADD_FAILURE() << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("OBSCURA_MAX_IMAGE_PIXELS"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

TEST_F(ImageLimits, HeaderChecksRejectDegenerateAndHostileShapes) {
  set_max_image_pixels(1000);
  EXPECT_NO_THROW(check_decoded_size("a", 10, 100, 1, 4));  // exactly the limit
  EXPECT_THROW(check_decoded_size("a", 11, 100, 1, 4), Error);
  EXPECT_NO_THROW(check_decoded_size("a", 10, 50, 1, 8));  // 8 channels: 2 pixels' worth each
  EXPECT_THROW(check_decoded_size("a", 10, 51, 1, 8), Error);
  for (auto [w, h] : {std::pair{0, 10}, {10, 0}, {-1, 10}, {10, -7}})
    EXPECT_THROW(check_decoded_size("a", w, h, 1, 3), Error) << w << "x" << h;
  EXPECT_THROW(check_decoded_size("a", 4, 4, 2, 3), Error);  // a volume
  EXPECT_THROW(check_decoded_size("a", 4, 4, 0, 3), Error);
  EXPECT_THROW(check_decoded_size("a", 4, 4, 1, 0), Error);
  EXPECT_THROW(check_decoded_size("a", 4, 4, 1, 65), Error);
  EXPECT_THROW(check_decoded_size("a", 4, 4, 1, 100000), Error);
  set_max_image_pixels(uint64_t(1) << 40);
  EXPECT_NO_THROW(check_decoded_size("a", 65536, 2, 1, 4));  // rows of 65536 × 4 values
  EXPECT_THROW(check_decoded_size("a", 65537, 2, 1, 4), Error);
  EXPECT_THROW(check_decoded_size("a", 1000000, 1, 1, 3), Error);  // fuzz finding (PFM)
  set_max_image_pixels(UINT64_MAX);  // products that wrap 64 bits are still refused
  EXPECT_THROW(check_decoded_size("a", INT64_MAX, INT64_MAX, 1, 64), Error);
}

TEST_F(ImageLimits, CliRefusesHugeInputWithBoundedMemory) {
  std::string file = write_file("huge.png", png_declaring(20000, 20000));
  std::string out = path("out.png");
  // Under a 2 GB address-space limit: decoding 20000² RGB as float would need 4.8 GB.
  auto r = test::run_shell(test::address_space_limit(2000000) + "'" + test::cli_path() +
                           "' image convert '" + file + "' '" + out + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.output.rfind("obscura: error: " + file + ": ", 0), 0u) << r.output;
  expect_limit_message(r.output, file);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ImageLimits, CliOptionAndVariableSetTheLimit) {
  std::string file = small_png("64.png", 64, 64);
  auto r =
      test::run_cli("image convert " + file + " " + path("a.exr") + " --max-image-pixels 4095");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("4095"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("a.exr")));
  r = test::run_cli("image convert " + file + " " + path("b.exr") + " --max-image-pixels 4096");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cli("image convert " + file + " " + path("c.exr") + " --max-image-pixels 0");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = test::run_cli("image convert " + file + " " + path("d.exr") + " --max-image-pixels -3");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = test::run_cli("image diff " + file + " " + file + " --max-image-pixels 100");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  r = test::run_cli("render --width 8 --height 8 --spp 1 -q -o " + path("r.png") +
                    " --environment " + file + " --max-image-pixels 100");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("64x64"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("r.png")));
  r = test::run_cli("render --width 8 --height 8 --spp 1 -q -o " + path("s.png") +
                    " --environment " + file);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::string convert(1, '\'');
  convert.append(test::cli_path()).append("' image convert ").append(file + " ");
  r = test::run_shell("OBSCURA_MAX_IMAGE_PIXELS=4095 " + convert + path("e.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_FALSE(fs::exists(path("e.exr")));
  r = test::run_shell("OBSCURA_MAX_IMAGE_PIXELS=4095 " + convert + path("f.exr") +
                      " --max-image-pixels 4096");  // the option wins
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(ImageLimits, DevicesAndFifosAreRefusedNotReadForever) {
  ASSERT_EQ(mkfifo(path("fifo.png").c_str(), 0600), 0);
  EXPECT_THROW(read_image(path("fifo.png")), Error);
  EXPECT_THROW(read_texture(path("fifo.png"), TextureEncoding::kSrgb), Error);
  auto r = test::run_cli("image convert /dev/zero " + path("out.png"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("/dev/zero: not a regular file"), std::string::npos) << r.output;
}

// Found by the image fuzz target: a 298-byte EXR whose "capDate" string attribute declares
// 1768161299 bytes (0x69640013, little-endian at offset 22), which OpenEXR allocates before
// reading. The header check refuses it first.
TEST_F(ImageLimits, ExrAttributeLargerThanTheFileIsRefused) {
  std::string file = test::source_path("fuzz/corpus/image/regress-exr-string-attribute-1.7gb.exr");
  std::ifstream in(file, std::ios::binary);
  std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_EQ(bytes.size(), 298u);
  for (auto read : {+[](const std::string&f, const std::vector<uint8_t>&) { read_image(f); },
                    +[](const std::string&, const std::vector<uint8_t>&b) {
                      decode_texture(b, "mem.exr", "exr", TextureEncoding::kLinear);
                    }}) {
    try {
      read(file, bytes);
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("'capDate' declares 1768161299 bytes"),
                std::string::npos)
          << e.what();
    }
  }
}

// Found by the image fuzz target: a 235-byte EXR whose data window is 16908288 × 2 pixels
// (iinfo reports it so); OpenEXR sized line buffers from it while opening, seconds of work
// before the pixel count could be checked. The header check refuses the width first.
TEST_F(ImageLimits, ExrDataWindowWiderThanARowIsRefused) {
  std::string file = test::source_path("fuzz/corpus/image/regress-exr-data-window-16m-wide.exr");
  try {
    read_image(file);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("dataWindow is 16908288 × 2 pixels"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace obscura

namespace obscura {
namespace {

// Every format Obscura writes reads back, from the file and from memory. (OpenImageIO 2.4's JPEG
// reader accepts only a "memreader" proxy: a reader of another type left every embedded JPEG —
// DamagedHelmet's five textures — undecoded. Its TIFF writer, writing through a proxy, left the
// image directory out of every TIFF Obscura wrote.)
TEST(EmbeddedImages, EveryFormatDecodesFromMemory) {
  std::string dir = test::make_temp_dir("obscura-embedded");
  Image grey(6, 4, 3);
  grey.data.assign(grey.data.size(), 0.2140f);  // sRGB code 128 in 8 bits
  for (const char* ext : {"png", "jpg", "tif", "exr", "hdr"}) {
    std::string file = dir + "/grey." + ext;
    write_image(file, grey);
    Image back = read_image(file);
    ASSERT_EQ(back.width, 6) << ext;
    std::ifstream in(file, std::ios::binary);
    std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in),
                               std::istreambuf_iterator<char>()};
    Texture t =
        decode_texture(bytes, std::string("model.glb: ") + ext, ext, TextureEncoding::kSrgb);
    EXPECT_EQ(t.width, 6) << ext;
    EXPECT_EQ(t.height, 4) << ext;
    bool linear_file = std::string(ext) == "exr" || std::string(ext) == "hdr";
    EXPECT_NEAR(t.texel(3, 2, 0), linear_file ? 0.2140f : 128 / 255.f, 0.01f) << ext;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace obscura

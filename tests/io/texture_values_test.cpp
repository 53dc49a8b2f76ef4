// Images read as scene data (textures, environment maps) carry no NaN or infinity into rendering:
// a float texel that is NaN becomes 0, one beyond its range (±1e12 for data and environment maps,
// [0, 1] for sRGB colour; ±inf included) the nearest bound, and each image that had any gets one
// warning naming its file and how many values were replaced — through every loader that reads
// images (JSON scene, OBJ's map_Kd, glTF images, --environment) — and a render of such a scene in
// either renderer gives finite pixels, with no non-finite value on the film.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "obscura/film/image.h"
#include "obscura/io/default_environment.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/io/image_io.h"
#include "obscura/io/json_scene.h"
#include "obscura/io/obj_loader.h"
#include "obscura/io/texture_loader.h"
#include "run_command.h"

namespace obscura {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// 2 × 2 RGB texels: four unusable values (NaN, +inf, −inf, 1e30) among eight of 0.5.
const std::vector<float> kHostileTexels = {kNaN,  0.5f, 0.5f, kInf,  0.5f, 0.5f,
                                           -kInf, 0.5f, 0.5f, 1e30f, 0.5f, 0.5f};
// What they must read as, in any order, as data (linear): NaN → 0, +inf and 1e30 → 1e12,
// −inf → −1e12; as an sRGB colour texture, within [0, 1]: NaN and −inf → 0, +inf and 1e30 → 1.
const std::vector<float> kSanitized = {-1e12f, 0,    0.5f, 0.5f, 0.5f,  0.5f,
                                       0.5f,   0.5f, 0.5f, 0.5f, 1e12f, 1e12f};
const std::vector<float> kSanitizedColour = {0,    0,    0.5f, 0.5f, 0.5f, 0.5f,
                                             0.5f, 0.5f, 0.5f, 0.5f, 1,    1};

void write_pfm(const std::string& path, const std::vector<float>& rgb) {
  std::ofstream out(path, std::ios::binary);
  out << "PF\n2 2\n-1.0\n";  // negative scale: little-endian
  out.write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size() * 4));
}

void write_exr(const std::string& path, const std::vector<float>& rgb) {
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path, OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
  out->close();
}

std::vector<float> sorted(std::vector<float> values) {
  std::sort(values.begin(), values.end());
  return values;
}

size_t warnings_naming(const std::vector<std::string>& warnings, const std::string& file) {
  return size_t(std::count_if(warnings.begin(), warnings.end(), [&](const std::string& w) {
    return w.find(file) != std::string::npos && w.find("4 texel values") != std::string::npos;
  }));
}

class TextureValues : public test::TempDirTest {};

TEST_F(TextureValues, NonFiniteTexelsAreReplacedAndCounted) {
  write_pfm(path("t.pfm"), kHostileTexels);
  write_exr(path("t.exr"), kHostileTexels);
  for (const char* name : {"t.pfm", "t.exr"}) {
    std::vector<std::string> warnings;
    Texture t = read_texture(path(name), TextureEncoding::kLinear, &warnings);
    ASSERT_EQ(t.texels_float.size(), 12u) << name;
    for (float v : t.texels_float) EXPECT_TRUE(std::isfinite(v)) << name;
    std::vector<float> got = sorted(t.texels_float);
    for (size_t i = 0; i < got.size(); ++i)
      EXPECT_FLOAT_EQ(got[i], kSanitized[i]) << name << " sorted texel " << i;
    ASSERT_EQ(warnings.size(), 1u) << name;
    EXPECT_NE(warnings[0].find(path(name)), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("4 texel values"), std::string::npos) << warnings[0];
  }
  // The same from memory (a glTF's embedded image), named by its source.
  std::ifstream in(path("t.pfm"), std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                   std::istreambuf_iterator<char>()};
  std::vector<std::string> warnings;
  Texture t =
      decode_texture(bytes, "scene.glb: images[2]", "pfm", TextureEncoding::kSrgb, &warnings);
  EXPECT_EQ(sorted(t.texels_float), kSanitizedColour);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("scene.glb: images[2]: 4 texel values"), std::string::npos)
      << warnings[0];
}

TEST_F(TextureValues, FiniteTexelsAreKeptAndNotWarnedAbout) {
  const std::vector<float> fine = {0, 0.25f, 1, 2, 1e6f, -3, 0.5f, 0.5f, 0.5f, 7, 8, 9};
  write_pfm(path("f.pfm"), fine);
  std::vector<std::string> warnings;
  Texture t = read_texture(path("f.pfm"), TextureEncoding::kLinear, &warnings);
  EXPECT_EQ(sorted(t.texels_float), sorted(fine));
  EXPECT_TRUE(warnings.empty());
  // As colour, within [0, 1]: the five values above 1 and the one below 0 are clamped.
  t = read_texture(path("f.pfm"), TextureEncoding::kSrgb, &warnings);
  EXPECT_EQ(sorted(t.texels_float),
            (std::vector<float>{0, 0, 0.25f, 0.5f, 0.5f, 0.5f, 1, 1, 1, 1, 1, 1}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("6 texel values"), std::string::npos) << warnings[0];
}

TEST_F(TextureValues, EveryLoaderWarnsOncePerImageNamingTheFile) {
  write_pfm(path("mr.pfm"), kHostileTexels);
  write_exr(path("base.exr"), kHostileTexels);
  write_pfm(path("env.pfm"), kHostileTexels);
  write_pfm(path("kd.pfm"), kHostileTexels);
  write_pfm(path("g.pfm"), kHostileTexels);
  write_pfm(path("cli-env.pfm"), kHostileTexels);

  std::ofstream(path("s.json")) << R"({"name": "s", "materials": {"m": {"type":
    "metallic-roughness", "base_color_texture": "base.exr", "metallic_roughness_texture":
    "mr.pfm"}, "n": {"type": "metallic-roughness", "metallic_roughness_texture": "mr.pfm"}},
    "objects": [{"name": "a", "shape": "sphere", "radius": 0.5, "material": "m"},
                {"name": "b", "shape": "sphere", "radius": 0.5, "material": "n"}],
    "environment": {"file": "env.pfm"}})";
  Scene json = load_json_scene(path("s.json"));
  for (const char* file : {"mr.pfm", "base.exr", "env.pfm"})
    EXPECT_EQ(warnings_naming(json.warnings, file), 1u) << file;
  for (const Texture& t : json.textures)
    for (float v : t.texels_float) ASSERT_TRUE(std::isfinite(v)) << t.source;

  std::ofstream(path("o.mtl")) << "newmtl m\nKd 1 1 1\nmap_Kd kd.pfm\n";
  std::ofstream(path("o.obj")) << "mtllib o.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                                  "vt 0 1\nusemtl m\nf 1/1 2/2 3/3\n";
  Scene obj = load_obj(path("o.obj"));
  EXPECT_EQ(warnings_naming(obj.warnings, "kd.pfm"), 1u);
  ASSERT_EQ(obj.textures.size(), 1u);
  for (float v : obj.textures[0].texels_float) EXPECT_TRUE(std::isfinite(v));

  std::ofstream(path("g.gltf")) << R"({"asset": {"version": "2.0"},
    "images": [{"uri": "g.pfm"}], "textures": [{"source": 0}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]})";
  Scene gltf = load_gltf(path("g.gltf"));
  EXPECT_EQ(warnings_naming(gltf.warnings, "g.pfm"), 1u) << testing::PrintToString(gltf.warnings);
  for (const Texture& t : gltf.textures)
    for (float v : t.texels_float) EXPECT_TRUE(std::isfinite(v)) << t.source;

  // --environment FILE: the map the command line adds to a loaded scene.
  Scene scene;
  apply_environment(scene, {.source = EnvironmentSource::kFile, .file = path("cli-env.pfm")});
  EXPECT_EQ(warnings_naming(scene.warnings, "cli-env.pfm"), 1u);
}

// Both renderers, a tiny frame of a scene whose base colour, metallic-roughness and environment
// images hold NaN and infinities: the pixels written are finite, and the warnings name the files.
TEST_F(TextureValues, ScenesWithHostileTexelsRenderFinitePixels) {
  write_pfm(path("mr.pfm"), kHostileTexels);
  write_pfm(path("base.pfm"), kHostileTexels);
  write_pfm(path("env.pfm"), kHostileTexels);
  std::ofstream(path("r.json")) << R"({"name": "r", "materials": {"m": {"type":
    "metallic-roughness", "base_color_texture": "base.pfm", "metallic_roughness_texture":
    "mr.pfm"}},
    "objects": [{"name": "ball", "shape": "sphere", "radius": 0.5, "material": "m"}],
    "cameras": [{"name": "c", "position": [0, 0, 3], "target": [0, 0, 0]}],
    "lights": [{"name": "l", "type": "point", "position": [1, 2, 3], "intensity": 10}],
    "environment": {"file": "env.pfm"}})";
  for (const char* renderer : {"path", "raster"}) {
    const std::string out = path(std::string(renderer) + ".pfm");
    auto r = test::run_cli("render " + path("r.json") + " --renderer " + renderer +
                           " --width 8 --height 8 --spp 1 -o " + out);
    ASSERT_EQ(r.exit_code, 0) << renderer << ": " << r.output;
    for (const char* file : {"mr.pfm", "base.pfm", "env.pfm"})
      EXPECT_NE(r.output.find(std::string(file) + ": 4 texel values"), std::string::npos)
          << renderer << ": " << r.output;
    // The CLI writes a non-finite film value as black and says so: there must be none.
    EXPECT_EQ(r.output.find("on the film"), std::string::npos) << renderer << ": " << r.output;
    Image image = read_image(out);
    for (float v : image.data) ASSERT_TRUE(std::isfinite(v)) << renderer;
  }
}

}  // namespace
}  // namespace obscura

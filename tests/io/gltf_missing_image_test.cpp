// An image a glTF file names but that is not there: found under its base name next to the model
// when it is there (a path from another machine), else one warning and, for a base colour
// texture, a magenta/black checker that shows in a render; data textures keep their factors.
#include "gltf_hostile.h"
#include "obscura/io/texture_loader.h"

namespace obscura::test {
namespace {

class GltfMissingImage : public GltfHostile {
 public:
  // A 2 × 2 square facing +Z with uvs over [0, 1]², one material using image 0 as `slot`.
  std::string quad(const std::string& name, const std::string& uri,
                   const std::string& slot = "baseColorTexture") {
    std::vector<uint8_t> bytes(4 * 12 + 4 * 8 + 6 * 2);
    const float positions[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const float uvs[8] = {0, 1, 1, 1, 1, 0, 0, 0};
    const uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + 48, uvs, sizeof uvs);
    std::memcpy(bytes.data() + 80, indices, sizeof indices);
    json pbr = {{"metallicFactor", 0}, {slot, {{"index", 0}}}};
    json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
              {"indices", 2},
              {"material", 0}}}}}}},
        {"materials", {{{"pbrMetallicRoughness", pbr}}}},
        {"textures", {{{"source", 0}}}},
        {"images", {{{"uri", uri}}}},
        {"buffers",
         {{{"byteLength", bytes.size()},
           {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
          {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
          {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
    };
    return write(name, doc);
  }
  static const MetallicRoughnessMaterial& pbr(const Scene& scene) {
    return std::get<MetallicRoughnessMaterial>(scene.materials.at(0).model);
  }
};

TEST_F(GltfMissingImage, BaseColourBecomesAMagentaBlackCheckerWithOneWarning) {
  Scene scene = load_gltf(quad("quad.gltf", "textures/absent.png"));
  EXPECT_EQ(count_warnings(scene, "absent.png"), 1);
  EXPECT_TRUE(has_warning(scene, "quad.gltf: images[0]: 'textures/absent.png' cannot be used"));
  EXPECT_TRUE(has_warning(scene, "magenta/black checker"));
  const TextureRef& ref = pbr(scene).base_color_texture;
  ASSERT_TRUE(ref.valid());
  const Texture& t = scene.textures.at(size_t(ref.texture));
  // Magenta (1, 0, 1) and black squares side by side.
  EXPECT_EQ(t.texel(0, 0, 0), 1.f);
  EXPECT_EQ(t.texel(0, 0, 1), 0.f);
  EXPECT_EQ(t.texel(0, 0, 2), 1.f);
  EXPECT_EQ(t.texel(t.width / 8, 0, 0), 0.f);
  EXPECT_EQ(t.texel(t.width / 8, 0, 2), 0.f);
}

TEST_F(GltfMissingImage, TheCheckerShowsInARender) {
  std::string path = quad("render.gltf", "absent.png");
  for (const char* renderer : {"raster", "path"}) {
    std::string out = dir + "/" + renderer + ".png";
    CommandResult r = run_cli("render " + path + " -o " + out + " --renderer " + renderer +
                              " --width 48 --height 48 --spp 4 --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Texture image = read_texture(out, TextureEncoding::kSrgb);
    int magenta = 0, dark = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        float red = image.texel(x, y, 0), green = image.texel(x, y, 1), blue = image.texel(x, y, 2);
        magenta += red > 2 * green + 0.1f && blue > 2 * green + 0.1f;
        dark += red + green + blue < 0.15f;
      }
    // The quad fills much of the frame; half of it is magenta, half black.
    EXPECT_GT(magenta, image.width * image.height / 10) << renderer;
    EXPECT_GT(dark, image.width * image.height / 20) << renderer;
  }
}

TEST_F(GltfMissingImage, DataTexturesKeepTheirFactors) {
  Scene scene = load_gltf(quad("data.gltf", "absent-mr.png", "metallicRoughnessTexture"));
  EXPECT_EQ(count_warnings(scene, "absent-mr.png"), 1);
  EXPECT_FALSE(pbr(scene).metallic_roughness_texture.valid());
  EXPECT_TRUE(scene.textures.empty());
}

TEST_F(GltfMissingImage, AFileFromAnotherMachineIsFoundByItsBaseNameNextToTheModel) {
  const std::string png = data_path("gltf/AnimatedCube/glTF/AnimatedCube_BaseColor.png");
  const int width = read_texture(png, TextureEncoding::kSrgb).width;
  std::filesystem::copy(png, dir + "/wood.png");
  std::filesystem::copy(png, dir + "/my wood.png");
  for (const std::string uri :
       {"C:\\Users\\artist\\textures\\wood.png", "/nonexistent-obscura-dir/wood.png",
        "../elsewhere/my%20wood.png"}) {
    Scene scene = load_gltf(quad("far.gltf", uri));
    std::string base = uri.find("my") != std::string::npos ? "my wood.png" : "wood.png";
    EXPECT_TRUE(has_warning(
        scene, "'" + uri + "' was not found; using '" + base + "' found next to the model instead"))
        << uri;
    const TextureRef& ref = pbr(scene).base_color_texture;
    ASSERT_TRUE(ref.valid()) << uri;
    EXPECT_EQ(scene.textures.at(size_t(ref.texture)).width, width) << uri;  // not the checker
    EXPECT_NE(scene.textures.at(size_t(ref.texture)).name, "missing-image placeholder");
  }
}

}  // namespace
}  // namespace obscura::test

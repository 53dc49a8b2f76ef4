// A corpus of files no one here wrote, through both renderers (issue 31): every Khronos sample
// model of tests/data/gltf/ (and of ../shared/assets/gltf/ when CI has it beside the clone) at
// t = 0 and, for animated files, at mid-animation and at the end; and OBJ/PLY/STL files with the
// quirks real exporters leave, written by the test. Each frame is tiny (48 × 48; the tracer 4
// spp, every sample through the pixel centre; the rasterizer as it comes) and must render without
// an exception, with finite pixels, visibly (the model covers pixels, and some pixel is lit), with
// the two renderers seeing the model at the same pixels (their id AOVs' hit masks agree on ≥ 97 %
// of the pixels: the silhouette, at mid-animation too) and with mean brightness over the model's
// pixels within a factor of kBrightnessFactor of each other.
//
// The expectations are independent of the renderers' code: the animation's length is read from
// the file's own JSON (the samplers' input accessors' "max", which glTF requires), the quirk files'
// geometry is written here, and the two renderers are two implementations checked against each
// other.
//
// Measured (docs/gltf-fidelity.md, "Corpus", for every model and time): masks agree on ≥ 0.9996
// of the pixels (one pixel of 2304 at worst), brightness ratios are ≤ 1.38 (TransmissionTest,
// which the rasterizer approximates), so no model is excluded. All 41 tests take
// about 10 s of CPU in one process (texture decoding dominates); the sanitized CI run leaves
// SharedGltf/ out (.ci/run).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "obscura/io/default_environment.h"
#include "obscura/io/scene_loader.h"
#include "obscura/render/render_frame.h"
#include "test_paths.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 48;
constexpr double kMaskAgreement = 0.97;
constexpr double kBrightnessFactor = 2;

// A model file the corpus renders; `path` empty: a placeholder that skips, saying why.
struct CorpusFile {
  std::string name, path, skip_reason;
};

void PrintTo(const CorpusFile& file, std::ostream* os) {
  *os << file.name;
}

// The model file of a Khronos sample folder: its .glb, else its .gltf, at the top or in the
// glTF-Binary/ and glTF/ variants.
std::optional<std::string> model_in(const fs::path& folder) {
  for (const char* sub : {"", "glTF-Binary", "glTF"}) {
    const fs::path dir = folder / sub;
    if (!fs::is_directory(dir)) continue;
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file() &&
          (entry.path().extension() == ".glb" || entry.path().extension() == ".gltf"))
        found.push_back(entry.path());
    std::sort(found.begin(), found.end(), [](const fs::path& a, const fs::path& b) {
      return std::make_pair(a.extension() != ".glb", a) <
             std::make_pair(b.extension() != ".glb", b);
    });
    if (!found.empty()) return found.front().string();
  }
  return std::nullopt;
}

std::vector<CorpusFile> models_under(const fs::path& root, const std::vector<std::string>& skip) {
  std::vector<CorpusFile> files;
  if (!fs::is_directory(root)) return files;
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || std::count(skip.begin(), skip.end(), name)) continue;
    if (std::optional<std::string> model = model_in(entry.path()))
      files.push_back({name, *model, ""});
  }
  std::sort(files.begin(), files.end(),
            [](const CorpusFile& a, const CorpusFile& b) { return a.name < b.name; });
  return files;
}

std::vector<std::string> names_of(const std::vector<CorpusFile>& files) {
  std::vector<std::string> names;
  for (const CorpusFile& f : files) names.push_back(f.name);
  return names;
}

std::vector<CorpusFile> suite_models() {
  return models_under(test::source_path("tests/data/gltf"), {});
}

// ../shared's models that the suite does not ship (those it does are rendered above); one
// placeholder that skips when ../shared is not beside the clone (a user's clone).
std::vector<CorpusFile> shared_models() {
  const fs::path root = test::source_path("../shared/assets/gltf");
  std::vector<CorpusFile> files = models_under(root, names_of(suite_models()));
  if (files.empty())
    files.push_back({"absent", "",
                     "no ../shared/assets/gltf beside the clone (CI has it; a user's clone does "
                     "not): only tests/data/gltf is rendered"});
  return files;
}

// What the test reads of a glTF file's own JSON (the first chunk of a .glb).
nlohmann::json gltf_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 20 && bytes.compare(0, 4, "glTF") == 0) {
    uint32_t length = 0;  // the JSON chunk's, after the 12-byte header and its own 8
    std::memcpy(&length, bytes.data() + 12, 4);
    bytes = bytes.substr(20, length);
  }
  return nlohmann::json::parse(bytes);
}

// The first animation's end (s): the largest of its samplers' input "max" (glTF requires min
// and max on animation inputs). Nothing for a file without animations.
std::optional<double> animation_end_s(const nlohmann::json& gltf) {
  if (!gltf.contains("animations") || gltf["animations"].empty()) return std::nullopt;
  double end = 0;
  for (const auto& sampler : gltf["animations"][0]["samplers"])
    end = std::max(end, gltf["accessors"][sampler["input"].get<size_t>()]["max"][0].get<double>());
  return end;
}

// Whether the file has skins or morph targets, which the loader poses at its time (rigid node
// animation is kept as keyframes, sampled at the shutter's time).
bool poses_at_load(const nlohmann::json& gltf) {
  if (gltf.contains("skins") && !gltf["skins"].empty()) return true;
  for (const auto& mesh : gltf.value("meshes", nlohmann::json::array()))
    for (const auto& primitive : mesh.value("primitives", nlohmann::json::array()))
      if (primitive.contains("targets")) return true;
  return false;
}

// A model as a user's first render gets it, but lit by a uniform white sky where it brings no
// light of its own (the fidelity suite's light; the studio map's importance tables would double
// the test's time).
Scene lit(Scene scene) {
  EnvironmentChoice white;
  white.source = EnvironmentSource::kWhite;
  if (!scene_has_own_light(scene)) apply_environment(scene, white);
  return scene;
}

Scene load_model(const std::string& path, double time_s) {
  GltfLoadOptions options;
  options.time_s = time_s;
  return lit(load_scene_file(path, options));
}

struct Frame {
  Image image, id;
};

Frame render_with(const Scene& scene, Camera camera, const char* renderer) {
  FrameSettings settings;
  settings.renderer = renderer_named(renderer);
  settings.samples_per_pixel = 4;
  settings.seed = 1;
  // Every tracer sample through the pixel centre, where the rasterizer looks: the id AOV is
  // then the centre's, as the rasterizer's.
  camera.film.filter = BoxFilter{1e-6};
  Film film(kSize, kSize);
  AovBuffers aovs(kSize, kSize);
  render_frame(scene, camera, settings, film, &aovs);
  return {film.to_image(), aovs.id()};
}

double luminance(const Image& image, int x, int y) {
  const Rgb c = image.rgb(x, y);
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

struct Comparison {
  double mask_agreement = 0, traced_mean = 0, raster_mean = 0;
  Rgb traced_rgb, raster_rgb;  // means over the pixels both see the model at
  int traced_covered = 0, raster_covered = 0;
};

// Renders `scene` by both renderers and checks what the file comment says; returns the numbers.
Comparison expect_both_renderers_agree(const Scene& scene, const std::string& what) {
  SCOPED_TRACE(what);
  Camera camera = scene.camera;
  camera.film.width_px = camera.film.height_px = kSize;
  const Frame traced = render_with(scene, camera, "path");
  const Frame rastered = render_with(scene, camera, "raster");
  Comparison c;
  int agree = 0, both = 0;
  double traced_sum = 0, raster_sum = 0, brightest = 0;
  bool finite = true;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      for (const Image* image : {&traced.image, &rastered.image})
        for (int ch = 0; ch < 3; ++ch) finite &= std::isfinite(image->at(x, y, ch));
      const bool in_traced = traced.id.at(x, y, 0) >= 0, in_raster = rastered.id.at(x, y, 0) >= 0;
      c.traced_covered += in_traced;
      c.raster_covered += in_raster;
      agree += in_traced == in_raster;
      brightest =
          std::max({brightest, luminance(traced.image, x, y), luminance(rastered.image, x, y)});
      if (in_traced && in_raster) {
        ++both;
        traced_sum += luminance(traced.image, x, y);
        raster_sum += luminance(rastered.image, x, y);
        c.traced_rgb += traced.image.rgb(x, y);
        c.raster_rgb += rastered.image.rgb(x, y);
      }
    }
  c.mask_agreement = double(agree) / (kSize * kSize);
  c.traced_mean = both ? traced_sum / both : 0;
  c.raster_mean = both ? raster_sum / both : 0;
  if (both) c.traced_rgb = c.traced_rgb / float(both), c.raster_rgb = c.raster_rgb / float(both);
  EXPECT_TRUE(finite);
  EXPECT_GT(brightest, 1e-3) << "an all-black frame";
  EXPECT_GE(c.traced_covered, 4) << "the tracer sees nothing of the model";
  EXPECT_GE(c.raster_covered, 4) << "the rasterizer draws nothing of the model";
  EXPECT_GE(c.mask_agreement, kMaskAgreement);
  if (both > 0 && std::max(c.traced_mean, c.raster_mean) > 1e-4) {
    EXPECT_LE(c.traced_mean, kBrightnessFactor * c.raster_mean);
    EXPECT_LE(c.raster_mean, kBrightnessFactor * c.traced_mean);
  }
  std::printf("corpus %-40s mask %.4f  covered %4d/%4d  mean %.4g / %.4g\n", what.c_str(),
              c.mask_agreement, c.traced_covered, c.raster_covered, c.traced_mean, c.raster_mean);
  return c;
}

class GltfCorpus : public ::testing::TestWithParam<CorpusFile> {};

TEST_P(GltfCorpus, RendersInBothRenderersThatAgree) {
  const CorpusFile& file = GetParam();
  if (file.path.empty()) GTEST_SKIP() << file.skip_reason;
  if (!fs::exists(file.path)) GTEST_SKIP() << file.path << " is gone since the tests were listed";
  const nlohmann::json gltf = gltf_json(file.path);
  std::vector<double> times = {0};
  if (std::optional<double> end = animation_end_s(gltf); end && *end > 0)
    times = {0, *end / 2, *end};
  Scene scene;
  ASSERT_NO_THROW(scene = load_model(file.path, 0));
  for (double t : times) {
    if (t > 0 && poses_at_load(gltf)) {
      ASSERT_NO_THROW(scene = load_model(file.path, t)) << t;
    }
    // The frame at t: an instantaneous shutter there.
    scene.camera.shutter.open_s = scene.camera.shutter.close_s = t;
    char label[32];
    std::snprintf(label, sizeof label, " t=%.3g s", t);
    ASSERT_NO_THROW(expect_both_renderers_agree(scene, file.name + label));
  }
}

INSTANTIATE_TEST_SUITE_P(SuiteGltf, GltfCorpus, ::testing::ValuesIn(suite_models()),
                         [](const auto& info) { return info.param.name; });
// Left out of the sanitized CI run (.ci/run), which would take minutes over them.
INSTANTIATE_TEST_SUITE_P(SharedGltf, GltfCorpus, ::testing::ValuesIn(shared_models()),
                         [](const auto& info) { return info.param.name; });

// The quirk files: a unit cube as exporters write it, oddly.
struct Cube {
  std::vector<Vector3f> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

Cube unit_cube() {
  Cube cube;
  for (int i = 0; i < 8; ++i)
    cube.vertices.push_back({i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f});
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads)
    for (std::array<int, 3> t : {std::array<int, 3>{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
      const Vector3f a = cube.vertices[size_t(t[0])], b = cube.vertices[size_t(t[1])],
                     c = cube.vertices[size_t(t[2])];
      // Outward: the normal points away from the centre (the origin).
      if (dot(cross(b - a, c - a), Vector3f(a.x + b.x + c.x, a.y + b.y + c.y, a.z + b.z + c.z)) < 0)
        std::swap(t[1], t[2]);
      cube.triangles.push_back(t);
    }
  return cube;
}

class QuirkFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("obscura-quirks-" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
  const Cube cube_ = unit_cube();
};

TEST_F(QuirkFiles, ObjWithAMissingMtllibCrlfAndNegativeIndices) {
  // Exporters name a .mtl that is not shipped with the file, end lines with CR LF, and refer to
  // vertices relative to the last one.
  std::ofstream out(path("cube.obj"), std::ios::binary);
  out << "# exported elsewhere\r\nmtllib cube_materials.mtl\r\no Cube\r\n";
  for (const Vector3f& v : cube_.vertices) out << "v " << v.x << " " << v.y << " " << v.z << "\r\n";
  out << "usemtl Painted\r\n";
  for (const auto& t : cube_.triangles)
    out << "f " << t[0] - 8 << " " << t[1] - 8 << " " << t[2] - 8 << "\r\n";
  out.close();
  Scene scene;
  ASSERT_NO_THROW(scene = lit(load_scene_file(path("cube.obj"))));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices.size(), 36u);
  expect_both_renderers_agree(scene, "obj missing mtllib");
}

TEST_F(QuirkFiles, PlyWithOnlyVertexColours) {
  // No normals, no texture coordinates, no material: red vertices (uchar), a binary body.
  std::ofstream out(path("cube.ply"), std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment only colours\nelement vertex 8\n"
         "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
         "property uchar green\nproperty uchar blue\nelement face 12\n"
         "property list uchar int vertex_indices\nend_header\n";
  for (const Vector3f& v : cube_.vertices) {
    const float xyz[3] = {v.x, v.y, v.z};
    const uint8_t rgb[3] = {230, 20, 20};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
    out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
  }
  for (const auto& t : cube_.triangles) {
    const uint8_t n = 3;
    out.write(reinterpret_cast<const char*>(&n), 1);
    out.write(reinterpret_cast<const char*>(t.data()), 12);
  }
  out.close();
  Scene scene;
  ASSERT_NO_THROW(scene = lit(load_scene_file(path("cube.ply"))));
  const Comparison c = expect_both_renderers_agree(scene, "ply vertex colours only");
  // The colours are the cube's: red under a white sky, in both renderers (the specular
  // reflection adds the same white to every channel: measured 0.99, 0.56, 0.56).
  for (Rgb rgb : {c.traced_rgb, c.raster_rgb}) {
    EXPECT_GT(rgb.r, 1.5f * rgb.g);
    EXPECT_NEAR(rgb.g, rgb.b, 0.01f);
  }
}

TEST_F(QuirkFiles, BinaryStlWhoseHeaderSaysSolid) {
  // Binary STL headers are free text, and CAD exporters start them with "solid": the file is
  // still binary (its size is 84 + 50 bytes a triangle).
  std::ofstream out(path("cube.stl"), std::ios::binary);
  char header[80] = {};
  std::snprintf(header, sizeof header, "solid cube exported as binary STL");
  out.write(header, 80);
  const auto count = uint32_t(cube_.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : cube_.triangles) {
    const Vector3f a = cube_.vertices[size_t(t[0])], b = cube_.vertices[size_t(t[1])],
                   c = cube_.vertices[size_t(t[2])];
    const Vector3f n = normalize(cross(b - a, c - a));
    const float values[12] = {n.x, n.y, n.z, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
    const uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
  out.close();
  ASSERT_EQ(fs::file_size(path("cube.stl")), 84u + 50u * 12u);
  Scene scene;
  ASSERT_NO_THROW(scene = lit(load_scene_file(path("cube.stl"))));
  size_t triangles = 0;
  for (const Mesh& mesh : scene.meshes) triangles += mesh.indices.size() / 3;
  EXPECT_EQ(triangles, 12u);  // read as binary, not as an empty ASCII solid
  expect_both_renderers_agree(scene, "binary stl saying solid");
}

}  // namespace
}  // namespace obscura

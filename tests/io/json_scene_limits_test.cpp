// A JSON scene from a hostile or careless source: paths that are not files, oversized and deeply
// nested documents, impossible sizes and reflectances, and huge numbers of shapes. Each is an
// error naming the file (and the JSON path), at once and in bounded memory.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "obscura/io/json_reader.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "run_command.h"

namespace obscura {
namespace {

namespace fs = std::filesystem;
using testing::HasSubstr;

class JsonSceneLimits : public test::TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    std::string file = path(name);
    std::ofstream(file) << text;
    return file;
  }
  // Loads `text` as scene.json and expects an error containing every fragment.
  void expect_error(const std::string& text, std::initializer_list<std::string> fragments) {
    std::string file = write("scene.json", text);
    try {
      load_scene_file(file);
      ADD_FAILURE() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("scene.json"));
      for (const std::string& f : fragments) EXPECT_THAT(e.what(), HasSubstr(f)) << text;
    }
  }
  static std::string object(const std::string& fields) {
    return R"({"materials": {"m": {"type": "diffuse"}}, "objects": [)"
           R"({"shape": "sphere", "material": "m"}, {"material": "m", )" +
           fields + "}]}";
  }
};

TEST_F(JsonSceneLimits, PathsThatAreNotRegularFilesFailAtOnce) {
  // A symlink to /dev/zero would be read forever; a FIFO would block forever on open.
  fs::create_symlink("/dev/zero", path("zero.json"));
  ASSERT_EQ(mkfifo(path("fifo.json").c_str(), 0600), 0);
  fs::create_directory(path("dir.json"));
  for (const char* name : {"zero.json", "fifo.json", "dir.json"}) {
    auto r = test::run_cli("info " + path(name));
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr(name));
    EXPECT_THAT(r.output, HasSubstr("expected a JSON file"));
  }
}

TEST_F(JsonSceneLimits, OversizedAndDeeplyNestedDocumentsAreRefused) {
  std::string big = path("big.json");
  {
    std::ofstream out(big);
    out << "{\"description\": \"" << std::string((64 << 20) + 10, 'x') << "\"}";
  }
  try {
    load_scene_file(big);
    ADD_FAILURE() << "a 64 MiB + 14 byte file was read";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("big.json"));
    EXPECT_THAT(e.what(), HasSubstr("64 MiB"));
  }
  fs::remove(big);
  // 65 levels: one more than the limit, reported where the 65th opens (line 1, column 65).
  std::string deep = std::string(65, '[') + std::string(65, ']');
  EXPECT_THROW(parse_json_text(deep, "deep.json"), Error);
  try {
    parse_json_text("{\"a\":" + std::string(100000, '['), "deep.json");
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("deep.json:1:69"));
    EXPECT_THAT(e.what(), HasSubstr("64 levels"));
  }
  // Brackets inside strings do not count.
  EXPECT_NO_THROW(parse_json_text("[\"" + std::string(1000, '[') + "\"]", "s.json"));
  EXPECT_NO_THROW(parse_json_text(std::string(64, '[') + std::string(64, ']'), "ok.json"));
}

TEST_F(JsonSceneLimits, SizesMustBePositiveAndFinite) {
  expect_error(object(R"("shape": "rectangle", "size": [-1, 2])"), {"$.objects[1].size"});
  expect_error(object(R"("shape": "rectangle", "size": [0, 2])"), {"$.objects[1].size"});
  expect_error(object(R"("shape": "box", "size": [1, 1e300, 1])"), {"$.objects[1].size"});
  expect_error(object(R"("shape": "sphere", "radius": -2)"), {"$.objects[1].radius"});
  expect_error(object(R"("shape": "sphere", "radius": 0)"), {"$.objects[1].radius"});
  expect_error(object(R"("shape": "mesh", "positions": [0,0,0, 1e39,0,0, 0,1,0], )"
                      R"("indices": [0,1,2])"),
               {"$.objects[1].positions", "vertex 1"});
  expect_error(R"({"objects": [{"shape": "box", "size": [1, 2, 3], "material": "m",)"
               R"( "transform": {"scale": 1e400}}]})",
               {"number overflow", "1e400"});  // not even a double: malformed JSON
}

TEST_F(JsonSceneLimits, RenderSettingsStayWithinTheCommandLinesRanges) {
  // The same range as --spp (2^20): a scene cannot ask for what the command line refuses.
  expect_error(R"({"render": {"spp": 2000000}})", {"$.render.spp", "1048576"});
  expect_error(R"({"render": {"spp": 0}})", {"$.render.spp"});
}

TEST_F(JsonSceneLimits, ReflectancesStayWithinOne) {
  expect_error(R"({"materials": {"m": {"type": "diffuse", "reflectance": 1e30}}})",
               {"$.materials.m.reflectance", "at most 1"});
  expect_error(R"({"materials": {"m": {"type": "diffuse", "reflectance": [0.5, 1.2, 0.5]}}})",
               {"$.materials.m.reflectance"});
  expect_error(R"({"materials": {"m": {"type": "metallic-roughness", "base_color": 2}}})",
               {"$.materials.m.base_color"});
  expect_error(R"({"materials": {"m": {"type": "dielectric", "transmittance": 1.5}}})",
               {"$.materials.m.transmittance"});
  expect_error(R"({"materials": {"m": {"type": "diffuse", "emission": 1e300}}})",
               {"$.materials.m.emission"});
}

TEST_F(JsonSceneLimits, ShapesShareOneUnitMeshPerKind) {
  std::string text = R"({"materials": {"m": {"type": "diffuse"}}, "objects": [)";
  for (int i = 0; i < 1000; ++i)
    text += std::string(i ? "," : "") + R"({"shape": "sphere", "material": "m", "radius": )" +
            std::to_string(0.5 + i * 0.001) + R"(, "transform": {"translate": [)" +
            std::to_string(i) + ",0,0]}}";
  text += R"(, {"shape": "box", "material": "m", "size": [1, 2, 3]})";
  text += R"(, {"shape": "box", "material": "m", "size": [4, 5, 6]}]})";
  Scene scene = load_scene_file(write("many.json", text));
  EXPECT_EQ(scene.meshes.size(), 2u);  // one sphere, one box
  EXPECT_EQ(scene.instances.size(), 1002u);
  // The instances carry the sizes: sphere 999 has radius 1.499 around (999, 0, 0).
  Point3f top = scene.instances[999].world_from_object(Point3f(0, 1, 0));
  EXPECT_NEAR(top.x, 999, 1e-3);
  EXPECT_NEAR(top.y, 1.499, 1e-5);
  Point3f corner = scene.instances[1001].world_from_object(Point3f(0.5f, 0.5f, 0.5f));
  EXPECT_NEAR(corner.x, 2, 1e-6);
  EXPECT_NEAR(corner.y, 2.5, 1e-6);
  EXPECT_NEAR(corner.z, 3, 1e-6);
}

}  // namespace
}  // namespace obscura

// Posing a loaded scene again (Scene::pose: a glTF file's animated skins and morph targets) and
// bringing a compilation up to date in place (TraceScene::update, RenderSession::scene_changed).
// The references are independent of the code under test: the file read afresh at that moment
// (whose skinning tests/io/gltf_deformation_test.cpp holds to glm), a new compilation of the
// same scene, and a lone render of a scene loaded at that moment.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include "obscura/io/gltf_loader.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/error.h"
#include "obscura/render/render_session.h"
#include "obscura/scene/shapes.h"
#include "obscura/trace/trace_scene.h"
#include "test_paths.h"

namespace obscura {
namespace {

const char* const kSkin = "gltf/SimpleSkin/SimpleSkin.gltf";
const char* const kMorph = "gltf/AnimatedMorphCube/AnimatedMorphCube.glb";

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  // std::equal, not memcmp: an empty vector's data() may be null, which memcmp must not see.
  return a.size() == b.size() && std::equal(reinterpret_cast<const char*>(a.data()),
                                            reinterpret_cast<const char*>(a.data() + a.size()),
                                            reinterpret_cast<const char*>(b.data()));
}

GltfLoadOptions at_moment(double time_s, double exposure_s) {
  GltfLoadOptions options;
  options.time_s = time_s;
  options.exposure_s = exposure_s;
  return options;
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  if (a.deformation.positions.size() != b.deformation.positions.size() ||
      a.deformation.normals.size() != b.deformation.normals.size())
    return false;
  for (size_t s = 0; s < a.deformation.positions.size(); ++s)
    if (!same_bytes(a.deformation.positions[s], b.deformation.positions[s])) return false;
  for (size_t s = 0; s < a.deformation.normals.size(); ++s)
    if (!same_bytes(a.deformation.normals[s], b.deformation.normals[s])) return false;
  return a.name == b.name && same_bytes(a.positions, b.positions) &&
         same_bytes(a.normals, b.normals) && same_bytes(a.tangents, b.tangents) &&
         same_bytes(a.indices, b.indices) && a.deformation.open_s == b.deformation.open_s &&
         a.deformation.close_s == b.deformation.close_s;
}

TEST(ScenePose, PosingAgainIsReadingTheFileAtThatMoment) {
  for (const char* file : {kSkin, kMorph}) {
    const std::string path = test::data_path(file);
    Scene scene = load_gltf(path);
    ASSERT_TRUE(scene.poser) << file;
    for (auto [time, exposure] : {std::pair{0.5, 0.0}, {1.7, 1.0 / 30}, {3.1, 0.0}, {0.2, 0.5}}) {
      const std::vector<uint32_t> posed = scene.pose(time, exposure);
      ASSERT_FALSE(posed.empty());
      const Scene read = load_gltf(path, at_moment(time, exposure));
      ASSERT_EQ(read.meshes.size(), scene.meshes.size());
      for (size_t m = 0; m < read.meshes.size(); ++m)
        EXPECT_TRUE(same_mesh(scene.meshes[m], read.meshes[m]))
            << file << " mesh " << m << " at " << time << " s over " << exposure << " s";
    }
  }
}

TEST(ScenePose, AFileWithoutAnimatedShapesHasNothingToPose) {
  Scene box = load_gltf(test::data_path("gltf/BoxAnimated/BoxAnimated.glb"));  // rigid motion only
  EXPECT_FALSE(box.poser);
  EXPECT_TRUE(box.pose(1.0, 0.0).empty());
}

TEST(ScenePose, NonFiniteMomentsAreRefused) {
  Scene scene = load_gltf(test::data_path(kSkin));
  EXPECT_THROW(scene.pose(std::nan(""), 0), Error);
  EXPECT_THROW(scene.pose(1, -1), Error);
  EXPECT_THROW(scene.pose(1, INFINITY), Error);
}

// What a grid of rays towards the scene's bounds meets, as bits.
std::vector<uint32_t> what_rays_hit(const TraceScene& trace, const Scene& scene, float time) {
  const Bounds3f b = scene.bounds();
  const Point3f centre{0.5f * (b.min.x + b.max.x), 0.5f * (b.min.y + b.max.y),
                       0.5f * (b.min.z + b.max.z)};
  const float reach = 2 * distance(b.min, b.max) + 1;
  std::vector<uint32_t> bits;
  auto put = [&](float v) { bits.push_back(std::bit_cast<uint32_t>(v)); };
  for (const Vector3f from :
       {Vector3f(0, 0.3f, 1), Vector3f(1, 0.2f, 0.1f), Vector3f(-0.4f, 1, 0.5f)})
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 24; ++x) {
        const Point3f target{b.min.x + (b.max.x - b.min.x) * (x + 0.5f) / 24,
                             b.min.y + (b.max.y - b.min.y) * (y + 0.5f) / 24, centre.z};
        Ray ray;
        ray.origin = centre + normalize(from) * reach;
        ray.direction = target - ray.origin;
        ray.time = time;
        const std::optional<SurfaceHit> hit = trace.intersect(ray);
        if (!hit) {
          bits.push_back(~0u);
          continue;
        }
        for (float v : {hit->t, hit->position.x, hit->position.y, hit->position.z,
                        hit->shading_normal.x, hit->shading_normal.y, hit->shading_normal.z,
                        hit->geometric_normal.x, hit->uv.x, hit->uv.y})
          put(v);
        bits.push_back(hit->mesh);
        bits.push_back(hit->primitive);
      }
  return bits;
}

// An instantaneous exposure at time 0 (a default Shutter is open for 1/60 s).
constexpr Shutter kStill{.open_s = 0, .close_s = 0};

std::shared_ptr<EmbreeDevice> device() {
  return std::make_shared<EmbreeDevice>();
}

TEST(TraceSceneUpdate, APosedSkinTracesAsANewCompilation) {
  for (const char* file : {kSkin, kMorph}) {
    Scene scene = load_gltf(test::data_path(file));
    TraceScene kept(scene, device(), {.shutter = kStill});
    size_t hit_entries = 0;
    for (double time : {0.6, 1.3, 2.9}) {
      const std::vector<uint32_t> posed = scene.pose(time, 0);
      ASSERT_TRUE(kept.update(scene, posed, kStill));
      const TraceScene fresh(scene, device(), {.shutter = kStill});
      const std::vector<uint32_t> seen = what_rays_hit(kept, scene, 0);
      EXPECT_EQ(seen, what_rays_hit(fresh, scene, 0)) << file << " at " << time << " s";
      EXPECT_EQ(kept.ray_epsilon(), fresh.ray_epsilon());
      EXPECT_EQ(kept.radius(), fresh.radius());
      hit_entries += seen.size() - size_t(std::count(seen.begin(), seen.end(), ~0u));
    }
    EXPECT_GT(hit_entries, 0u) << file << ": the rays should meet the model";
  }
}

TEST(TraceSceneUpdate, ADeformingSkinOverTheSameShutterTracesAsANewCompilation) {
  // Motion blur: the skin is a prototype with vertices per time step over the shutter.
  Scene scene = load_gltf(test::data_path(kSkin), at_moment(0.5, 0.2));
  const Shutter shutter{.open_s = 0.4, .close_s = 0.6};
  TraceScene kept(scene, device(), {.shutter = shutter});
  ASSERT_TRUE(kept.has_motion());
  // Posed elsewhere but over the same interval's length: the same step count (a test of the
  // in-place rebuild, not a frame a sequence would render).
  const std::vector<uint32_t> posed = scene.pose(1.5, 0.2);
  ASSERT_TRUE(kept.update(scene, posed, shutter));
  const TraceScene fresh(scene, device(), {.shutter = shutter});
  for (float time : {0.4f, 0.5f, 0.6f})
    EXPECT_EQ(what_rays_hit(kept, scene, time), what_rays_hit(fresh, scene, time)) << time;
}

TEST(TraceSceneUpdate, AnAnimatedInstanceUnderAStillShutterIsPlacedAgain) {
  const Scene scene = load_gltf(test::data_path("gltf/BoxAnimated/BoxAnimated.glb"));
  TraceScene kept(scene, device(), {.shutter = kStill});
  for (double time : {0.7, 2.2}) {
    const Shutter still{.open_s = time, .close_s = time};
    EXPECT_FALSE(kept.serves(still)) << "the box is elsewhere at " << time << " s";
    ASSERT_TRUE(kept.update(scene, {}, still));
    const TraceScene fresh(scene, device(), {.shutter = still});
    EXPECT_EQ(what_rays_hit(kept, scene, float(time)), what_rays_hit(fresh, scene, float(time)));
  }
}

// Two boxes sharing one mesh (an Embree prototype) and a lamp above them.
Scene shared_boxes() {
  Scene scene;
  scene.materials.push_back(diffuse_material("grey", Rgb(0.5f)));
  scene.materials.push_back(diffuse_material("lamp", Rgb(0.f), Rgb(5.f)));
  const uint32_t box = scene.add_mesh(make_box({1, 1, 1}), Transform::translate({-1, 0, 0}));
  Instance second = scene.instances.front();
  second.world_from_object = Transform::translate({1.2f, 0, 0});
  scene.instances.push_back(second);
  Mesh lamp = make_rectangle(0.5f, 0.5f);
  lamp.material = 1;
  scene.add_mesh(std::move(lamp), Transform::translate({0, 2, 0}));
  scene.meshes[box].material = 0;
  scene.camera.world_from_camera = AnimatedTransform(Transform::translate({0, 0.5f, 5}));
  return scene;
}

TEST(TraceSceneUpdate, ASharedMeshChangedInPlaceTracesAsANewCompilation) {
  Scene scene = shared_boxes();
  TraceScene kept(scene, device(), {.shutter = kStill});
  ASSERT_EQ(kept.prototype_count(), 1u);
  for (Point3f& p : scene.meshes[0].positions) p = Point3f(p.x * 1.3f, p.y * 0.8f, p.z);
  const uint32_t changed[] = {0};
  ASSERT_TRUE(kept.update(scene, changed, kStill));
  const TraceScene fresh(scene, device(), {.shutter = kStill});
  EXPECT_EQ(what_rays_hit(kept, scene, 0), what_rays_hit(fresh, scene, 0));
}

TEST(TraceSceneUpdate, WhatOnlyANewCompilationCanDoIsRefused) {
  Scene scene = shared_boxes();
  TraceScene kept(scene, device(), {.shutter = kStill});
  const std::vector<uint32_t> before = what_rays_hit(kept, scene, 0);
  // The lamp's triangles are a light's: moving them needs the lights compiled again.
  const uint32_t lamp[] = {1};
  for (Point3f& p : scene.meshes[1].positions) p.y += 0.1f;
  EXPECT_FALSE(kept.update(scene, lamp, kStill));
  // Another vertex count.
  Scene grown = shared_boxes();
  grown.meshes[0] = make_sphere(0.5f, 8);
  const uint32_t box[] = {0};
  EXPECT_FALSE(kept.update(grown, box, kStill));
  // A refusal changes nothing.
  EXPECT_EQ(what_rays_hit(kept, shared_boxes(), 0), before);
  // What moves over an open shutter stands still under a closed one: another form.
  Scene moving = load_gltf(test::data_path("gltf/BoxAnimated/BoxAnimated.glb"));
  TraceScene blurred(moving, device(), {.shutter = Shutter{.open_s = 0, .close_s = 0.1}});
  EXPECT_FALSE(blurred.update(moving, {}, Shutter{.open_s = 1, .close_s = 1}));
}

TEST(TraceSceneUpdate, MotionOverAnotherShutterTracesAsANewCompilation) {
  // Where the motion keeps its time-step count over the new interval, the instances take their
  // new steps in place; where it does not, the update is refused. Either way, no stale motion.
  const Scene moving = load_gltf(test::data_path("gltf/BoxAnimated/BoxAnimated.glb"));
  std::optional<TraceScene> blurred;
  blurred.emplace(moving, device(),
                  TraceSceneOptions{.shutter = Shutter{.open_s = 0, .close_s = 0.1}});
  int updated = 0;
  for (double open : {0.3, 1.0, 1.9}) {
    const Shutter shutter{.open_s = open, .close_s = open + 0.1};
    if (!blurred->update(moving, {}, shutter)) {
      blurred.emplace(moving, device(), TraceSceneOptions{.shutter = shutter});
      continue;
    }
    ++updated;
    const TraceScene fresh(moving, device(), {.shutter = shutter});
    for (float u : {0.f, 0.5f, 1.f}) {
      const float time = float(shutter.time_at(u));
      EXPECT_EQ(what_rays_hit(*blurred, moving, time), what_rays_hit(fresh, moving, time))
          << open << " s";
    }
  }
  EXPECT_GT(updated, 0);
}

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

TEST(RenderSession, ASkinPosedPerFrameRendersAsTheFileLoadedAtEachMoment) {
  const std::string path = test::data_path(kSkin);
  Scene scene = load_scene(path);
  Camera camera = scene.camera;
  camera.film.width_px = 40;
  camera.film.height_px = 30;
  for (const char* renderer : {"path", "raster"}) {
    RenderSession session(scene);
    const FrameSettings settings{
        .renderer = renderer_named(renderer), .samples_per_pixel = 2, .seed = 5};
    const double times[] = {0.25, 1.0, 1.75, 3.0};
    for (double time : times) {
      session.scene_changed(scene.pose(time, 0));
      const Scene alone = load_scene(path, at_moment(time, 0));
      // The automatic camera frames the file at time 0 whatever the moment.
      ASSERT_EQ(alone.camera.world_from_camera.at(0).matrix(),
                scene.camera.world_from_camera.at(0).matrix());
      EXPECT_TRUE(same_bits(session.render(camera, settings, false).finished(),
                            render_frame(alone, camera, settings, false).finished()))
          << renderer << " at " << time << " s";
    }
    EXPECT_EQ(session.compilations(), 1) << renderer;
    EXPECT_EQ(session.updates(), 3) << renderer;
  }
}

}  // namespace
}  // namespace obscura

// The tracer's ray throughput next to raw Embree on the same rays, and the path tracer's time to
// reach Cycles' error on the reference Cornell box.
//   rays/<scene>/<kind>/<obscura|embree_raw>/<threads>: primary (one per pixel of a 640×360
//     view), shadow (from each primary hit towards a point above the scene) and incoherent
//     bounce rays (cosine-distributed about the hit normal). "obscura" goes through
//     TraceScene::intersect (closest hit + the SurfaceHit shading needs) and
//     TraceScene::occluded; "embree_raw" calls rtcIntersect1/rtcOccluded1 on an Embree scene
//     built with the same flags.
//     Scenes with instances are built the same way on both sides: a mesh placed once is copied
//     into world space, a mesh placed several times is one Embree scene under one
//     RTC_GEOMETRY_TYPE_INSTANCE per placement (TraceScene's default policy, redone here with
//     raw Embree calls).
//   cornell/path/<spp>: renders ../shared/reference/cornell at 128², reports RMSE vs the
//     16,384-spp Cycles reference.
//   cornell/equal_time/<solid_angle|area>/<spp>: the same render, area lights sampled by solid
//     angle or by area: RMSE·√(CPU seconds), whose ratio is the RMSE ratio at equal time.
// Scenes: the Stanford bunny (../shared/assets/meshes/stanford_bunny/bun_zipper.ply, 69 k
// triangles), a 4×4 grid of bunny instances (one mesh, 16 placements, 1.1 M triangles) and, when
// OBSCURA_BENCH_OBJ names it, the 1 M-triangle sphere grid written by
// ../shared/tools/peers/embree/run.sh --write-obj.
// Run: OBSCURA_BENCH_OBJ=spheres.obj build/bench/tracer_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <embree3/rtcore.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "../tests/trace/trace_test_scenes.h"
#include "obscura/film/image_metrics.h"
#include "obscura/io/image_io.h"
#include "obscura/io/scene_loader.h"
#include "obscura/math/rng.h"
#include "obscura/math/sampling.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"

namespace obscura {
namespace {

// ../shared beside the checkout, found from this source file's location.
std::string shared(const std::string& relative) {
  return (std::filesystem::path(__FILE__).parent_path() / "../../shared" / relative).string();
}

// Vertices and faces of an ASCII PLY (the Stanford scans), or of an OBJ with triangles.
Mesh read_mesh(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot open");
  Mesh mesh;
  mesh.name = path;
  std::string line;
  if (path.ends_with(".ply")) {
    size_t vertices = 0, faces = 0;
    while (std::getline(in, line) && line != "end_header") {
      std::istringstream w(line);
      std::string a, b;
      size_t n;
      if (w >> a >> b >> n && a == "element") (b == "vertex" ? vertices : faces) = n;
    }
    for (size_t i = 0; i < vertices && std::getline(in, line); ++i) {
      std::istringstream w(line);
      Point3f p;
      w >> p.x >> p.y >> p.z;
      mesh.positions.push_back(p);
    }
    for (size_t i = 0; i < faces && std::getline(in, line); ++i) {
      std::istringstream w(line);
      uint32_t n, a, b, c;
      w >> n >> a >> b >> c;
      mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }
    return mesh;
  }
  while (std::getline(in, line)) {
    std::istringstream w(line);
    std::string tag;
    w >> tag;
    if (tag == "v") {
      Point3f p;
      w >> p.x >> p.y >> p.z;
      mesh.positions.push_back(p);
    } else if (tag == "f") {
      std::string v;
      while (w >> v) mesh.indices.push_back(uint32_t(std::stoul(v) - 1));
    }
  }
  return mesh;
}

struct RayBatch {
  std::vector<Ray> primary, shadow, bounce;
};

struct BenchScene {
  Scene scene;
  std::unique_ptr<TraceScene> trace;
  RTCDevice raw_device = nullptr;
  RTCScene raw = nullptr;
  RayBatch rays;
};

RTCGeometry raw_triangles(RTCDevice device, const Mesh& m, const Transform& world_from_object) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 12, m.positions.size()));
  auto* i = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, m.triangle_count()));
  for (size_t k = 0; k < m.positions.size(); ++k) {
    Point3f p = world_from_object(m.positions[k]);
    v[3 * k] = p.x, v[3 * k + 1] = p.y, v[3 * k + 2] = p.z;
  }
  for (size_t k = 0; k < m.indices.size(); ++k) i[k] = m.indices[k];
  rtcCommitGeometry(g);
  return g;
}

RTCScene raw_scene(RTCDevice device) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  return scene;
}

void build_raw(BenchScene& s) {
  s.raw_device = rtcNewDevice(nullptr);
  s.raw = raw_scene(s.raw_device);
  std::vector<int> uses(s.scene.meshes.size(), 0);
  for (const Instance& in : s.scene.instances) ++uses[in.mesh];
  std::vector<RTCScene> prototypes(s.scene.meshes.size(), nullptr);
  for (const Instance& in : s.scene.instances) {
    const Mesh& m = s.scene.meshes[in.mesh];
    if (uses[in.mesh] == 1) {
      RTCGeometry g = raw_triangles(s.raw_device, m, in.world_from_object);
      rtcAttachGeometry(s.raw, g);
      rtcReleaseGeometry(g);
      continue;
    }
    if (!prototypes[in.mesh]) {
      prototypes[in.mesh] = raw_scene(s.raw_device);
      RTCGeometry g = raw_triangles(s.raw_device, m, Transform());
      rtcAttachGeometry(prototypes[in.mesh], g);
      rtcReleaseGeometry(g);
      rtcCommitScene(prototypes[in.mesh]);
    }
    RTCGeometry g = rtcNewGeometry(s.raw_device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, prototypes[in.mesh]);
    float xfm[3][4];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) xfm[r][c] = float(in.world_from_object.matrix().m[r][c]);
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xfm);
    rtcCommitGeometry(g);
    rtcAttachGeometry(s.raw, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(s.raw);
  for (RTCScene p : prototypes)
    if (p) rtcReleaseScene(p);  // the instances hold their own references
}

// A scene of one mesh, placed once.
Scene single(Mesh mesh) {
  Scene scene;
  scene.name = mesh.name;
  scene.materials = {diffuse_material("grey", Rgb(0.5f))};
  scene.add_meshes({std::move(mesh)});
  return scene;
}

// Frames the scene's bounds from the front-top and builds the three ray sets.
BenchScene make_bench_scene(Scene scene) {
  BenchScene s;
  s.scene = std::move(scene);
  Bounds3f b = s.scene.bounds();
  Point3f c = b.min + (b.max - b.min) * 0.5f;
  float r = 0.5f * distance(b.min, b.max);
  Camera camera =
      testing::make_camera({c.x, c.y + 0.6 * r, c.z + 1.6 * r}, {c.x, c.y, c.z}, 640, 45);
  camera.film.height_px = 360;
  s.trace = std::make_unique<TraceScene>(s.scene, std::make_shared<EmbreeDevice>());
  build_raw(s);
  Point3f light(c.x + r, c.y + 3 * r, c.z + r);
  Pcg32 rng(1);
  for (int y = 0; y < 360; ++y)
    for (int x = 0; x < 640; ++x) {
      Ray ray = camera.generate_ray({x + 0.5, y + 0.5})->to_ray();
      ray.t_min = 0;
      s.rays.primary.push_back(ray);
      std::optional<SurfaceHit> hit = s.trace->intersect(ray);
      if (!hit) continue;
      Normal3f n = face_forward(hit->geometric_normal, -ray.direction);
      Ray shadow;
      shadow.origin = offset_ray_origin(hit->position, n, to_vector(n), s.trace->ray_epsilon());
      shadow.direction = light - shadow.origin;
      shadow.t_max = 1;
      s.rays.shadow.push_back(shadow);
      ShadingFrame frame = ShadingFrame::from_normal(to_vector(n));
      Ray bounce;
      bounce.origin = shadow.origin;
      bounce.direction =
          frame.to_world(sample_cosine_hemisphere({rng.next_float(), rng.next_float()}));
      s.rays.bounce.push_back(bounce);
    }
  return s;
}

Mesh bunny_mesh() {
  return read_mesh(shared("assets/meshes/stanford_bunny/bun_zipper.ply"));
}

BenchScene& bunny() {
  static BenchScene s = make_bench_scene(single(bunny_mesh()));
  return s;
}

// 16 bunnies on a 4 × 4 grid, each turned differently: one mesh, 16 Embree instances.
BenchScene* bunny_grid() {
  static BenchScene s = [] {
    Scene scene = single(bunny_mesh());
    scene.instances.clear();
    for (int i = 0; i < 16; ++i) {
      Instance& in = scene.instances.emplace_back();
      in.name = "bunny";
      in.world_from_object =
          Transform::translate({0.2 * (i % 4), 0, -0.2 * (i / 4)}) * Transform::rotate_y(0.4 * i);
    }
    return make_bench_scene(std::move(scene));
  }();
  return &s;
}

BenchScene* spheres() {
  static std::unique_ptr<BenchScene> s = [] {
    const char* path = std::getenv("OBSCURA_BENCH_OBJ");
    return path ? std::make_unique<BenchScene>(make_bench_scene(single(read_mesh(path)))) : nullptr;
  }();
  return s.get();
}

enum Kind { kPrimary, kShadow, kBounce };
enum Impl { kObscura, kRaw };

const std::vector<Ray>& rays_of(const BenchScene& s, Kind kind) {
  return kind == kPrimary ? s.rays.primary : kind == kShadow ? s.rays.shadow : s.rays.bounce;
}

float trace_one(const BenchScene& s, const Ray& r, Kind kind, Impl impl) {
  if (impl == kObscura) {
    if (kind == kShadow) return s.trace->occluded(r) ? 1.f : 0.f;
    std::optional<SurfaceHit> hit = s.trace->intersect(r);
    return hit ? hit->t : 0.f;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if (kind == kShadow) {
    RTCRay q{};
    q.org_x = r.origin.x, q.org_y = r.origin.y, q.org_z = r.origin.z;
    q.dir_x = r.direction.x, q.dir_y = r.direction.y, q.dir_z = r.direction.z;
    q.tnear = r.t_min, q.tfar = r.t_max, q.mask = ~0u;
    rtcOccluded1(s.raw, &context, &q);
    return q.tfar < 0 ? 1.f : 0.f;
  }
  RTCRayHit q{};
  q.ray.org_x = r.origin.x, q.ray.org_y = r.origin.y, q.ray.org_z = r.origin.z;
  q.ray.dir_x = r.direction.x, q.ray.dir_y = r.direction.y, q.ray.dir_z = r.direction.z;
  q.ray.tnear = r.t_min, q.ray.tfar = r.t_max, q.ray.mask = ~0u;
  q.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(s.raw, &context, &q);
  return q.hit.geomID != RTC_INVALID_GEOMETRY_ID ? q.ray.tfar : 0.f;
}

void bench_rays(benchmark::State& state, BenchScene* (*scene)(), Kind kind, Impl impl) {
  BenchScene* s = scene();
  if (!s) {
    state.SkipWithError("set OBSCURA_BENCH_OBJ to the peer's sphere-grid OBJ");
    return;
  }
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  const std::vector<Ray>& rays = rays_of(*s, kind);
  for (auto _ : state) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
                        float sum = 0;
                        for (size_t i = range.begin(); i < range.end(); ++i)
                          sum += trace_one(*s, rays[i], kind, impl);
                        benchmark::DoNotOptimize(sum);
                      });
  }
  state.counters["Mrays/s"] = benchmark::Counter(double(rays.size()) * state.iterations() * 1e-6,
                                                 benchmark::Counter::kIsRate);
}

BenchScene* bunny_ptr() {
  return &bunny();
}

void register_ray_benchmarks() {
  const char* kinds[] = {"primary", "shadow", "bounce"};
  const char* impls[] = {"obscura", "embree_raw"};
  for (auto [name, scene] :
       {std::pair{"bunny", &bunny_ptr}, std::pair{"bunny_grid_16", &bunny_grid},
        std::pair{"spheres_1M", &spheres}})
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 2; ++i)
        benchmark::RegisterBenchmark(
            (std::string("rays/") + name + "/" + kinds[k] + "/" + impls[i]).c_str(),
            [scene, k, i](benchmark::State& st) { bench_rays(st, scene, Kind(k), Impl(i)); })
            ->Arg(1)
            ->Arg(2)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
}

// glTF's MetalRoughSpheresNoTextures: 98 placements of one sphere mesh among 123 instances
// (1.04 M rendered triangles, 12 k stored).
const Scene& metal_rough_spheres() {
  static Scene s = load_scene_file(
      shared("assets/gltf/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb"));
  return s;
}

const Scene& bunny_grid_scene() {
  return bunny_grid()->scene;
}

// Compiling a scene into a TraceScene (Embree BVHs, shading data, lights), with the default
// instancing or with every instance copied into world space: build time and the bytes of
// geometry handed to Embree grow with unique triangles in the first case, with rendered
// triangles in the second.
void build_trace_scene(benchmark::State& state, const Scene& (*scene_of)(), Instancing instancing) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  const Scene& scene = scene_of();
  auto device = std::make_shared<EmbreeDevice>();
  for (auto _ : state) {
    TraceScene trace(scene, device, {.instancing = instancing});
    benchmark::DoNotOptimize(trace.radius());
  }
  // Vertex and index bytes: each mesh once per Embree prototype or flattened copy.
  std::vector<int> uses(scene.meshes.size(), 0);
  for (const Instance& in : scene.instances) ++uses[in.mesh];
  double bytes = 0;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    int copies = instancing == Instancing::kNever ? uses[m] : std::min(uses[m], 1);
    bytes += copies * 12.0 * (scene.meshes[m].vertex_count() + scene.meshes[m].triangle_count());
  }
  state.counters["embree_input_MB"] = bytes / 1e6;
}

void register_build_benchmarks() {
  for (auto [name, scene] : {std::pair{"bunny_grid_16", &bunny_grid_scene},
                             std::pair{"metal_rough_spheres", &metal_rough_spheres}})
    for (auto [mode, instancing] :
         {std::pair{"instanced", Instancing::kAuto}, std::pair{"flattened", Instancing::kNever}})
      benchmark::RegisterBenchmark(
          (std::string("build/") + name + "/" + mode).c_str(),
          [scene, instancing](benchmark::State& st) { build_trace_scene(st, scene, instancing); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
}

// The reference Cornell box at 128², path traced at state.range(0) spp with 2 threads.
void cornell_path(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  Scene scene = load_scene_file(shared("reference/cornell/cornell.glb"));
  Camera camera = testing::make_camera({0, 1, 3.9}, {0, 1, 0}, 128, 39.597752709049864);
  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Image reference = read_image(shared("reference/cornell/cornell_ref.exr"));
  double rmse = 0;
  uint64_t seed = 100;
  for (auto _ : state) {
    Film film(128, 128);
    render(trace, camera, PathTracer(), {.samples_per_pixel = int(state.range(0)), .seed = seed++},
           film);
    rmse += obscura::rmse(film.to_image(), reference, 3);
  }
  state.counters["rmse"] = rmse / state.iterations();
}

// The same render at state.range(0) spp, area lights sampled by solid angle or by area. Error
// falls as 1/√time, so RMSE·√seconds is the error either reaches in one second: the ratio of
// the two is the ratio of their RMSEs at equal time. Seconds are CPU seconds of the whole
// process (all threads), which other processes on a loaded machine disturb far less than wall
// time; render_s is the wall time.
void cornell_equal_time(benchmark::State& state, AreaLightSampling sampling) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  Scene scene = load_scene_file(shared("reference/cornell/cornell.glb"));
  Camera camera = testing::make_camera({0, 1, 3.9}, {0, 1, 0}, 128, 39.597752709049864);
  TraceScene trace(scene, std::make_shared<EmbreeDevice>(), {.area_light_sampling = sampling});
  Image reference = read_image(shared("reference/cornell/cornell_ref.exr"));
  double rmse = 0, seconds = 0, cpu_seconds = 0;
  uint64_t seed = 100;
  for (auto _ : state) {
    Film film(128, 128);
    std::clock_t cpu_start = std::clock();
    RenderStats stats = render(trace, camera, PathTracer(),
                               {.samples_per_pixel = int(state.range(0)), .seed = seed++}, film);
    cpu_seconds += double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    rmse += obscura::rmse(film.to_image(), reference, 3);
    seconds += stats.seconds;
  }
  double n = double(state.iterations());
  state.counters["rmse"] = rmse / n;
  state.counters["render_s"] = seconds / n;
  state.counters["cpu_s"] = cpu_seconds / n;
  state.counters["rmse_x_sqrt_cpu_s"] = rmse / n * std::sqrt(cpu_seconds / n);
}

BENCHMARK_CAPTURE(cornell_equal_time, solid_angle, AreaLightSampling::kSolidAngle)
    ->Name("cornell/equal_time/solid_angle")
    ->Arg(64)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(cornell_equal_time, area, AreaLightSampling::kArea)
    ->Name("cornell/equal_time/area")
    ->Arg(64)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK(cornell_path)
    ->Name("cornell/path")
    ->Arg(64)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

[[maybe_unused]] const bool registered =
    (register_ray_benchmarks(), register_build_benchmarks(), true);

}  // namespace
}  // namespace obscura

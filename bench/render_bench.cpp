// The foundation's hot paths, next to raw Embree on the same rays:
//   ray_query/*: closest-hit queries for the Cornell box's primary rays, through Obscura's
//     EmbreeScene and through rtcIntersect1 directly (the peer), single thread.
//   render/*: the default direct-lighting render at 256×256, 8 spp, at 1 and 2 threads.
// Run: build/bench/render_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <embree3/rtcore.h>
#include <tbb/global_control.h>

#include <vector>

#include "obscura/scene/builtin_scenes.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"

namespace obscura {
namespace {

constexpr int kSize = 256;

std::vector<Ray> primary_rays(const Camera& camera) {
  std::vector<Ray> rays;
  for (int y = 0; y < camera.film.height_px; ++y)
    for (int x = 0; x < camera.film.width_px; ++x)
      rays.push_back(camera.generate_ray({x + 0.5, y + 0.5})->to_ray());
  return rays;
}

Scene bench_scene() {
  Scene scene = make_cornell_box();
  scene.camera.film.width_px = scene.camera.film.height_px = kSize;
  return scene;
}

void ray_query_obscura(benchmark::State& state) {
  Scene scene = bench_scene();
  auto device = std::make_shared<EmbreeDevice>();
  EmbreeScene embree(device);
  for (const Mesh& m : scene.meshes) embree.add_triangle_mesh(m.positions, m.indices);
  embree.commit();
  std::vector<Ray> rays = primary_rays(scene.camera);
  for (auto _ : state) {
    float sum = 0;
    for (const Ray& r : rays)
      if (auto hit = embree.intersect(r)) sum += hit->t;
    benchmark::DoNotOptimize(sum);
  }
  state.counters["rays/s"] =
      benchmark::Counter(double(rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
}

void ray_query_embree_raw(benchmark::State& state) {
  Scene scene = bench_scene();
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene rtc_scene = rtcNewScene(device);
  rtcSetSceneFlags(rtc_scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(rtc_scene, RTC_BUILD_QUALITY_HIGH);
  for (const Mesh& m : scene.meshes) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 12, m.positions.size()));
    auto* i = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, m.triangle_count()));
    for (size_t k = 0; k < m.positions.size(); ++k)
      v[3 * k] = m.positions[k].x, v[3 * k + 1] = m.positions[k].y, v[3 * k + 2] = m.positions[k].z;
    for (size_t k = 0; k < m.indices.size(); ++k) i[k] = m.indices[k];
    rtcCommitGeometry(g);
    rtcAttachGeometry(rtc_scene, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(rtc_scene);
  std::vector<Ray> rays = primary_rays(scene.camera);
  for (auto _ : state) {
    float sum = 0;
    for (const Ray& r : rays) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit q{};
      q.ray.org_x = r.origin.x, q.ray.org_y = r.origin.y, q.ray.org_z = r.origin.z;
      q.ray.dir_x = r.direction.x, q.ray.dir_y = r.direction.y, q.ray.dir_z = r.direction.z;
      q.ray.tnear = 0, q.ray.tfar = r.t_max, q.ray.mask = ~0u;
      q.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(rtc_scene, &context, &q);
      if (q.hit.geomID != RTC_INVALID_GEOMETRY_ID) sum += q.ray.tfar;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["rays/s"] =
      benchmark::Counter(double(rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
  rtcReleaseScene(rtc_scene);
  rtcReleaseDevice(device);
}

void render_direct_lighting(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  Scene scene = bench_scene();
  auto device = std::make_shared<EmbreeDevice>();
  TraceScene trace_scene(scene, device);
  RenderSettings settings{.samples_per_pixel = 8, .seed = 0};
  uint64_t rays = 0;
  for (auto _ : state) {
    Film film(kSize, kSize);
    rays += render(trace_scene, scene.camera, DirectLightingIntegrator(), settings, film).rays.total();
  }
  state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}

BENCHMARK(ray_query_obscura)->Name("ray_query/obscura")->Unit(benchmark::kMillisecond);
BENCHMARK(ray_query_embree_raw)->Name("ray_query/embree_raw")->Unit(benchmark::kMillisecond);
BENCHMARK(render_direct_lighting)
    ->Name("render/direct_lighting")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace obscura

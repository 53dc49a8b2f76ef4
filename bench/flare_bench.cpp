// Ghost flares of the README's night street (scenes/night-street-flare.json: the double-Gauss
// 50 mm at f/8, uncoated, 960×540, six lamps and car lights, a window and the moon as sources):
// what `--flare` adds to a render, at 1 thread and at all of the machine's threads. Also the
// same lens single-coated (the default), whose fainter ghosts are skipped more often.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <string>
#include <thread>

#include "obscura/camera/lens_system_projection.h"
#include "obscura/io/scene_loader.h"
#include "obscura/render/lens_flare.h"

namespace {

using namespace obscura;

const Scene& night_street() {
  static const Scene scene =
      load_scene(std::string(OBSCURA_SOURCE_DIR) + "/scenes/night-street-flare.json");
  return scene;
}

int threads_of(const benchmark::State& state) {
  return state.range(0) > 0 ? int(state.range(0)) : int(std::thread::hardware_concurrency());
}

void run(benchmark::State& state, const LensCoating& coating) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads_of(state));
  const Scene& scene = night_street();
  Camera camera = scene.camera;
  std::get<LensSystemProjection>(camera.projection).coating = coating;
  FlareStats stats;
  for (auto _ : state) benchmark::DoNotOptimize(lens_flare_image(scene, camera, {}, &stats).data);
  state.counters["ghosts"] = stats.ghosts_traced;
  state.counters["skipped"] = stats.ghosts_skipped;
  state.counters["Mrays"] = stats.rays * 1e-6;
}

void BM_FlareNightStreetUncoated(benchmark::State& state) {
  run(state, LensCoating{});
}
void BM_FlareNightStreetCoated(benchmark::State& state) {
  run(state, quarter_wave_coating());
}

// Argument: threads (0 = all).
BENCHMARK(BM_FlareNightStreetUncoated)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_FlareNightStreetCoated)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

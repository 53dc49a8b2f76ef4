// Scene loading: time to load the Stanford bunny (ASCII PLY), DamagedHelmet (GLB with five
// 2048² JPEGs) and a generated 5-million-triangle binary PLY, with the in-memory size of the
// scene (bytes per triangle) and the peak memory of a process that does nothing but load it.
//
//   build/bench/scene_load_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "obscura/io/scene_loader.h"

namespace {

std::string shared(const std::string& relative) {
  return std::string(OBSCURA_SOURCE_DIR) + "/../shared/" + relative;
}

// A binary little-endian PLY: an n × n grid of vertices on a gently curved sheet, two triangles
// per cell. n = 1582 gives 2 · 1581² = 4,999,122 triangles.
std::string generated_mesh() {
  static std::string path;
  if (!path.empty()) return path;
  path = (std::filesystem::temp_directory_path() / "obscura_bench_5m.ply").string();
  const int n = 1582;
  std::ofstream out(path, std::ios::binary);
  size_t faces = 2 * size_t(n - 1) * (n - 1);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << size_t(n) * n
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << faces
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      float p[3] = {float(i) / n, 0.1f * std::sin(float(i + j) / 50), float(j) / n};
      out.write(reinterpret_cast<const char*>(p), sizeof p);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      for (auto tri : {std::array<int, 3>{a, c, b}, std::array<int, 3>{b, c, d}}) {
        out.put(3);
        out.write(reinterpret_cast<const char*>(tri.data()), sizeof(int) * 3);
      }
    }
  return path;
}

// Peak resident memory (MB) of a child process that loads the scene once: fork, load, report
// ru_maxrss through a pipe. The child starts as a copy of this process, so its baseline (the
// resident size at the fork) is reported too and subtracted.
double child_peak_load_mb(const std::string& path) {
  int fds[2];
  if (pipe(fds) != 0) return -1;
  pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    double result = -1;
    try {
      rusage before{};
      getrusage(RUSAGE_SELF, &before);
      obscura::Scene scene = obscura::load_scene_file(path);
      rusage after{};
      getrusage(RUSAGE_SELF, &after);
      result = double(after.ru_maxrss - before.ru_maxrss) / 1024.0;
    } catch (...) {
    }
    if (write(fds[1], &result, sizeof result) != sizeof result) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  double result = -1;
  if (read(fds[0], &result, sizeof result) != sizeof result) result = -1;
  close(fds[0]);
  waitpid(pid, nullptr, 0);
  return result;
}

void load(benchmark::State& state, const std::string& path) {
  size_t triangles = 0, bytes = 0;
  for (auto _ : state) {
    obscura::Scene scene = obscura::load_scene_file(path);
    obscura::SceneStats s = scene.stats();
    triangles = s.unique_triangles;
    bytes = s.memory_bytes;
    benchmark::DoNotOptimize(scene);
  }
  state.counters["triangles"] = double(triangles);
  state.counters["scene_MB"] = double(bytes) / 1e6;
  state.counters["bytes_per_tri"] = triangles ? double(bytes) / double(triangles) : 0;
  state.counters["peak_load_MB"] = child_peak_load_mb(path);
  state.counters["Mtri_per_s"] =
      benchmark::Counter(double(triangles) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_bunny_ply(benchmark::State& state) {
  load(state, shared("assets/meshes/stanford_bunny/bun_zipper.ply"));
}
void BM_damaged_helmet_glb(benchmark::State& state) {
  load(state, shared("assets/gltf/DamagedHelmet/DamagedHelmet.glb"));
}
void BM_generated_5M_ply(benchmark::State& state) {
  load(state, generated_mesh());
}

BENCHMARK(BM_bunny_ply)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_damaged_helmet_glb)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_generated_5M_ply)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

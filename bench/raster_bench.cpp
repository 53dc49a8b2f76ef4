// The rasterizer on the workloads of the llvmpipe peer benchmark (../shared/tools/peers/llvmpipe:
// its README and lpbench.cpp define them), at 1920×1080, depth test LESS, no MSAA:
//   mesh       84 UV spheres, 999,936 triangles, one indexed draw; mesh_cull with back-face culling
//   fill       100 full-viewport triangles back to front; fill_f2b front to back
//   tiny       4,150,048 triangles of about one pixel
// with the two shaders of that benchmark: gouraud (Blinn-Phong per vertex) and phong (per pixel),
// written here as C++ programs that compute what its GLSL computes. A frame is clear + draw.
// Counters: tris/s; covered_px/s (fragments rasterized, depth test off) and passed_px/s
// (fragments passing LESS), counted once per workload outside the timing, as lpbench does.
//
//   build/bench/raster_bench --benchmark_filter='mesh/gouraud' (arguments: threads)
//
// With OBSCURA_RASTER_BENCH_DUMP=DIR each benchmark also draws one frame with the aovs on and
// writes DIR/<workload>_<shader>_<threads>.bin: per pixel, row by row, colour r g b, depth and view
// depth as float32, then the primitive ids as uint32 — to compare two builds' images.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "obscura/raster/phong.h"
#include "obscura/raster/pipeline.h"

namespace obscura::raster {
namespace {

constexpr int kWidth = 1920, kHeight = 1080;

struct BenchVertex {
  Point3f position;
  Vector3f normal;
  Rgb color;
};

struct Workload {
  std::vector<BenchVertex> vertices;
  std::vector<uint32_t> indices;
  float mvp[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};  // row-major
  Point3f eye{0, 0, 3};
  bool cull = false;
};

OBSCURA_RASTER_INLINE Vector4f transform(const float m[4][4], Point3f p) {
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
          m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3],
          m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3]};
}

// The benchmark's lighting: colour·(0.15 + 0.85·max(N·L, 0)) + 0.5·max(N·H, 0)^32.
OBSCURA_RASTER_INLINE Vector3f unit(Vector3f v) {
  return v * (1.f / std::sqrt(dot(v, v)));
}

OBSCURA_RASTER_INLINE Rgb bench_lighting(Vector3f n, Vector3f l, Point3f p, Point3f eye,
                                         Rgb color) {
  n = unit(n);
  Vector3f v = unit(eye - p);
  Vector3f h = unit(l + v);
  float d = positive_part(dot(n, l));
  float s = specular_power(positive_part(dot(n, h)), 32);
  return color * (0.15f + 0.85f * d) + Rgb(0.5f * s);
}

struct GouraudBenchProgram {
  using Vertex = BenchVertex;
  struct Varyings {
    Rgb color;
  };
  const Workload* w;
  Vector3f to_light;
  VertexOutput<Varyings> vertex(const BenchVertex& v) const {
    return {transform(w->mvp, v.position),
            {bench_lighting(v.normal, to_light, v.position, w->eye, v.color)}};
  }
  Rgb fragment(const Varyings& v, FragmentInfo) const { return v.color; }
};

struct PhongBenchProgram {
  using Vertex = BenchVertex;
  struct Varyings {
    Point3f position;
    Vector3f normal;
    Rgb color;
  };
  const Workload* w;
  Vector3f to_light;
  VertexOutput<Varyings> vertex(const BenchVertex& v) const {
    return {transform(w->mvp, v.position), {v.position, v.normal, v.color}};
  }
  Rgb fragment(const Varyings& v, FragmentInfo) const {
    return bench_lighting(v.normal, to_light, v.position, w->eye, v.color);
  }
};

Rgb hue(float h) {
  float c[3];
  for (int i = 0; i < 3; ++i) {
    float t = h + i / 3.f;
    t -= std::floor(t);
    c[i] = 0.35f + 0.6f * (0.5f + 0.5f * std::cos(6.2831853f * t));
  }
  return {c[0], c[1], c[2]};
}

uint32_t hash32(uint32_t x) {
  x ^= x >> 16, x *= 0x7feb352dU, x ^= x >> 15, x *= 0x846ca68bU, x ^= x >> 16;
  return x;
}
float hash_unit(uint32_t x) {
  return float(hash32(x) & 0xFFFFFF) / float(0x1000000);
}

// (a) a 12 × 7 grid of UV spheres (96 slices, 63 stacks, radius 0.98, pole triangles dropped),
// counter-clockwise from outside, seen from z = 17.5 with a 45° vertical field of view.
Workload make_spheres() {
  const int columns = 12, rows = 7, slices = 96, stacks = 63;
  Workload w;
  for (int gy = 0; gy < rows; ++gy)
    for (int gx = 0; gx < columns; ++gx) {
      Point3f centre((gx - (columns - 1) / 2.f) * 2, (gy - (rows - 1) / 2.f) * 2, 0);
      Rgb color = hue(float(gy * columns + gx) / float(columns * rows));
      uint32_t base = uint32_t(w.vertices.size());
      for (int s = 0; s <= stacks; ++s) {
        float phi = 3.14159265f * s / stacks;
        for (int l = 0; l <= slices; ++l) {
          float theta = 6.2831853f * l / slices;
          Vector3f n(std::sin(phi) * std::cos(theta), std::cos(phi),
                     std::sin(phi) * std::sin(theta));
          w.vertices.push_back({centre + n * 0.98f, n, color});
        }
      }
      for (int s = 0; s < stacks; ++s)
        for (int l = 0; l < slices; ++l) {
          uint32_t a = base + s * (slices + 1) + l, b = a + 1, c = a + slices + 1, d = c + 1;
          uint32_t tris[2][3] = {{a, c, b}, {b, c, d}};
          for (int k = 0; k < 2; ++k) {
            if ((k == 0 && s == 0) || (k == 1 && s == stacks - 1)) continue;  // degenerate poles
            Point3f p0 = w.vertices[tris[k][0]].position, p1 = w.vertices[tris[k][1]].position,
                    p2 = w.vertices[tris[k][2]].position;
            if (dot(cross(p1 - p0, p2 - p0), p0 - centre) < 0) std::swap(tris[k][1], tris[k][2]);
            w.indices.insert(w.indices.end(), tris[k], tris[k] + 3);
          }
        }
    }
  const float aspect = float(kWidth) / kHeight, f = 1 / std::tan(22.5f * 3.14159265f / 180);
  const float n = 1, far = 100, distance = 17.5f;
  float m[4][4] = {
      {f / aspect, 0, 0, 0},
      {0, f, 0, 0},
      {0, 0, (far + n) / (n - far), (far + n) / (n - far) * -distance + 2 * far * n / (n - far)},
      {0, 0, -1, distance}};
  std::copy(&m[0][0], &m[0][0] + 16, &w.mvp[0][0]);
  w.eye = Point3f(0, 0, distance);
  return w;
}

// (b) 100 triangles covering the viewport (circumradius 3.2 in NDC), at NDC depths 0.9 … −0.9.
Workload make_fill(bool front_to_back) {
  const int n = 100;
  Workload w;
  for (int i = 0; i < n; ++i) {
    int k = front_to_back ? n - 1 - i : i;  // k = 0 is the farthest
    float z = 0.9f - 1.8f * k / (n - 1);
    float rotation = 6.2831853f * hash_unit(1000 + k);
    Rgb color = hue(float(k) / n);
    uint32_t base = uint32_t(w.vertices.size());
    for (int j = 0; j < 3; ++j) {
      float a = rotation + j * 2.0943951f;
      w.vertices.push_back(
          {Point3f(3.2f * std::cos(a), 3.2f * std::sin(a), z),
           Vector3f(0.8f * std::cos(a + 0.7f * j), 0.8f * std::sin(a + 1.3f * j), 1), color});
    }
    w.indices.insert(w.indices.end(), {base, base + 1, base + 2});
  }
  return w;
}

// (c) two layers of jittered grids of ~1-pixel triangles, the second nearer and drawn second.
Workload make_tiny() {
  const double cell = std::sqrt(2.0);
  const int columns = int(std::lround(kWidth / cell)), rows = int(std::lround(kHeight / cell));
  Workload w;
  for (int layer = 0; layer < 2; ++layer) {
    double ox = layer ? -0.7 : 0, oy = layer ? -0.7 : 0;
    float z = layer ? -0.5f : 0.5f;
    double sx = (kWidth + (layer ? 1.4 : 0)) / columns, sy = (kHeight + (layer ? 1.4 : 0)) / rows;
    uint32_t base = uint32_t(w.vertices.size());
    for (int r = 0; r <= rows; ++r)
      for (int c = 0; c <= columns; ++c) {
        uint32_t id = uint32_t(layer * 7919 * 7919 + r * 7919 + c);
        bool border = r == 0 || c == 0 || r == rows || c == columns;
        double jx = border ? 0 : (hash_unit(id * 3 + 1) - 0.5) * 0.4;
        double jy = border ? 0 : (hash_unit(id * 3 + 2) - 0.5) * 0.4;
        double px = ox + c * sx + jx, py = oy + r * sy + jy;
        float a = 0.05f * c + 0.031f * r, b = 0.043f * r - 0.02f * c;
        w.vertices.push_back(
            {Point3f(float(px / kWidth * 2 - 1), float(1 - py / kHeight * 2), z),
             Vector3f(0.6f * std::sin(a), 0.6f * std::cos(b), 1),
             hue(0.37f * layer + 0.5f * float(c) / columns + 0.3f * float(r) / rows)});
      }
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) {
        uint32_t a = base + r * (columns + 1) + c, b = a + 1, d = a + columns + 1, e = d + 1;
        if ((r + c) & 1)
          w.indices.insert(w.indices.end(), {a, d, b, b, d, e});
        else
          w.indices.insert(w.indices.end(), {a, d, e, a, e, b});
      }
  }
  return w;
}

const Workload& workload(const std::string& name) {
  static std::map<std::string, Workload> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Workload w = name.starts_with("mesh") ? make_spheres()
               : name == "fill"         ? make_fill(false)
               : name == "fill_f2b"     ? make_fill(true)
                                        : make_tiny();
  w.cull = name == "mesh_cull";
  return cache.emplace(name, std::move(w)).first->second;
}

// The frame's buffers as raw little-endian arrays (see the header comment), for comparisons.
void dump_frame(const RenderTarget& t, const std::string& path) {
  std::vector<float> floats;
  std::vector<uint32_t> ids;
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x) {
      const Rgb c = t.color_at(x, y);
      floats.insert(floats.end(), {c.r, c.g, c.b, t.depth_at(x, y), t.view_depth_at(x, y)});
      ids.push_back(t.primitive_id_at(x, y));
    }
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return;
  std::fwrite(floats.data(), sizeof(float), floats.size(), f);
  std::fwrite(ids.data(), sizeof(uint32_t), ids.size(), f);
  std::fclose(f);
}

template <class P>
void run(benchmark::State& state, const std::string& name, const std::string& shader) {
  const Workload& w = workload(name);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
  P program{&w, normalize(Vector3f(0.4f, 0.6f, 0.7f))};
  RenderTarget target(kWidth, kHeight);
  DrawState draw_state;
  draw_state.cull = w.cull ? CullMode::kBack : CullMode::kNone;
  const Rgb clear(0.05f, 0.05f, 0.08f);
  for (auto _ : state) {
    target.clear(clear);
    draw_with_depth_func<DepthFunc::kLess>(target, draw_state, program, w.vertices, w.indices);
    benchmark::DoNotOptimize(target.color_group(0));
    benchmark::ClobberMemory();
  }
  if (const char* dir = std::getenv("OBSCURA_RASTER_BENCH_DUMP")) {
    RenderTarget frame(kWidth, kHeight, 1, /*aovs=*/true);
    frame.clear(clear);
    draw_with_depth_func<DepthFunc::kLess>(frame, draw_state, program, w.vertices, w.indices);
    dump_frame(frame, std::string(dir) + "/" + name + "_" + shader + "_" +
                          std::to_string(state.range(0)) + ".bin");
  }
  // Fragment counts, outside the timing: additive blending of 1 per fragment.
  auto count = [&](DepthFunc func) {
    RenderTarget counts(kWidth, kHeight);
    counts.clear();
    DrawState s = draw_state;
    s.depth_func = func;
    s.blend = BlendMode::kAdd;
    struct One {
      using Vertex [[maybe_unused]] = BenchVertex;
      struct Varyings {
        float unused;
      };
      const Workload* w;
      VertexOutput<Varyings> vertex(const BenchVertex& v) const {
        return {transform(w->mvp, v.position), {0}};
      }
      Rgb fragment(const Varyings&, FragmentInfo) const { return Rgb(1.f); }
    };
    draw(counts, s, One{&w}, w.vertices, w.indices);
    double total = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) total += counts.color_at(x, y).r;
    return total;
  };
  const double triangles = double(w.indices.size() / 3);
  state.counters["tris/s"] =
      benchmark::Counter(triangles, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["covered_px/s"] =
      benchmark::Counter(count(DepthFunc::kAlways), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["passed_px/s"] =
      benchmark::Counter(count(DepthFunc::kLess), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["threads"] = double(state.range(0));
}

void register_all() {
  for (const char* name : {"mesh", "mesh_cull", "fill", "fill_f2b", "tiny"}) {
    benchmark::RegisterBenchmark(
        (std::string(name) + "/gouraud").c_str(),
        [name](benchmark::State& s) { run<GouraudBenchProgram>(s, name, "gouraud"); })
        ->Arg(1)
        ->Arg(2)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MeasureProcessCPUTime()
        ->MinWarmUpTime(0.2);
    benchmark::RegisterBenchmark(
        (std::string(name) + "/phong").c_str(),
        [name](benchmark::State& s) { run<PhongBenchProgram>(s, name, "phong"); })
        ->Arg(1)
        ->Arg(2)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MeasureProcessCPUTime()
        ->MinWarmUpTime(0.2);
  }
}

const bool registered = (register_all(), true);

}  // namespace
}  // namespace obscura::raster

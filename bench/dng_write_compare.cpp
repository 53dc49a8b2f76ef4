// The DNG write's throughput against libtiff's own uncompressed write of the same 16-bit 4K
// mosaic, run side by side: the writers alternate round by round (and swap order every round),
// so both see the same machine load. Reports per writer the median wall and CPU time of one
// write, and Obscura's throughput relative to libtiff's (libtiff's time / Obscura's: ≥ 0.8 is
// the goal), with the load average before and after.
//
//   build/bench/dng_write_compare [ROUNDS=15] [DIRECTORY=$TMPDIR or /tmp]
//
// Writers:
//   obscura        write_dng (no ground truth): libtiff encodes into memory, then the atomic
//                  writer: a temporary file, every write checked, fsync, rename
//   libtiff        TIFFOpen on the file, TIFFWriteScanline per row, no compression, TIFFClose
//   libtiff+fsync  the same and fsync before the close: the durability write_dng promises
#include <fcntl.h>
#include <sys/resource.h>
#include <tiffio.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "obscura/io/dng_file.h"
#include "obscura/sensor/sensor_capture.h"
#include "sensor_bench_inputs.h"

namespace {

using namespace obscura;

using bench::kHeight;
using bench::kWidth;

RawCapture capture_4k() {
  return capture_raw(bench::film_4k(), SensorSpec{}, bench::sensor_exposure(), 0);
}

void libtiff_write(const std::string& path, const RawCapture& capture, bool sync) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0644);
  TIFF* t = fd >= 0 ? TIFFFdOpen(fd, path.c_str(), "w") : nullptr;
  if (!t) {
    std::fprintf(stderr, "cannot open %s\n", path.c_str());
    std::exit(1);
  }
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, uint32_t(kWidth));
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, uint32_t(kHeight));
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, uint16_t(1));
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, uint16_t(16));
  TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, uint32_t(32));
  for (uint32_t y = 0; y < uint32_t(kHeight); ++y)
    TIFFWriteScanline(t, const_cast<uint16_t*>(capture.raw.data()) + size_t(y) * kWidth, y, 0);
  TIFFFlush(t);
  if (sync) ::fsync(fd);
  TIFFClose(t);  // closes fd
}

double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

struct Writer {
  const char* name;
  std::function<void()> write;
  std::vector<double> wall, cpu;
};

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
  const char* tmp = std::getenv("TMPDIR");
  const std::filesystem::path dir = argc > 2 ? argv[2] : tmp ? tmp : "/tmp";
  const std::string dng = (dir / "obscura-compare.dng").string();
  const std::string tif = (dir / "obscura-compare.tif").string();
  const RawCapture capture = capture_4k();
  DngWriteOptions options;
  options.ground_truth = false;
  std::vector<Writer> writers = {
      {"obscura", [&] { write_dng(dng, capture, options); }, {}, {}},
      {"libtiff", [&] { libtiff_write(tif, capture, false); }, {}, {}},
      {"libtiff+fsync", [&] { libtiff_write(tif, capture, true); }, {}, {}},
  };
  for (Writer& w : writers) w.write();  // warm the page cache and the codecs plugin
  std::printf("4K mosaic (%d x %d, 16-bit, %.1f MB), %d rounds, alternating, in %s\n", kWidth,
              kHeight, kWidth * kHeight * 2 / 1e6, rounds, dir.c_str());
  std::printf("load average before: %s\n", load_average().c_str());
  for (int round = 0; round < rounds; ++round)
    for (size_t k = 0; k < writers.size(); ++k) {
      Writer& w = writers[round % 2 ? writers.size() - 1 - k : k];
      const double cpu0 = cpu_seconds();
      const auto wall0 = std::chrono::steady_clock::now();
      w.write();
      w.wall.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
      w.cpu.push_back(cpu_seconds() - cpu0);
    }
  std::printf("load average after:  %s\n", load_average().c_str());
  const double base_wall = median(writers[1].wall), base_cpu = median(writers[1].cpu);
  std::printf("%-14s %10s %10s %14s %14s\n", "writer", "wall ms", "CPU ms", "vs libtiff wall",
              "vs libtiff CPU");
  for (const Writer& w : writers)
    std::printf("%-14s %10.1f %10.1f %14.2f %14.2f\n", w.name, 1e3 * median(w.wall),
                1e3 * median(w.cpu), base_wall / median(w.wall), base_cpu / median(w.cpu));
  std::filesystem::remove(dng);
  std::filesystem::remove(tif);
  return 0;
}

// The raw sensor at 4K (3840 × 2160): the capture (every noise source on), its development
// (Malvar demosaicing, white balance, colour matrix), and the DNG write against libtiff's own
// uncompressed write of the same 16-bit mosaic (the file's bytes are the same size; the DNG adds
// its tags, Obscura's write goes through the codecs plugin's in-memory encoder and an atomic,
// flushed file).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tiffio.h>

#include <filesystem>
#include <string>
#include <thread>

#include "obscura/io/atomic_file.h"
#include "obscura/io/dng_file.h"
#include "obscura/sensor/isp.h"
#include "obscura/sensor/sensor_capture.h"
#include "sensor_bench_inputs.h"

namespace {

using namespace obscura;

using bench::film_4k;
using bench::kHeight;
using bench::kWidth;

int threads_of(const benchmark::State& state) {
  return state.range(0) > 0 ? int(state.range(0)) : int(std::thread::hardware_concurrency());
}

void BM_SensorCapture4k(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads_of(state));
  const Image film = film_4k();
  uint64_t seed = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(capture_raw(film, SensorSpec{}, bench::sensor_exposure(), seed++));
}

void BM_SensorDevelop4k(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads_of(state));
  const RawCapture capture = capture_raw(film_4k(), SensorSpec{}, bench::sensor_exposure(), 0);
  for (auto _ : state) benchmark::DoNotOptimize(develop_raw(capture, DemosaicMethod::kMalvar));
}

std::string scratch(const char* name) {
  return (std::filesystem::temp_directory_path() / name).string();
}

void BM_DngWrite4k(benchmark::State& state) {
  const RawCapture capture = capture_raw(film_4k(), SensorSpec{}, bench::sensor_exposure(), 0);
  DngWriteOptions options;
  options.ground_truth = false;
  const std::string path = scratch("obscura-bench.dng");
  for (auto _ : state) write_dng(path, capture, options);
  state.SetBytesProcessed(int64_t(state.iterations()) * kWidth * kHeight * 2);
  std::filesystem::remove(path);
}

// The same bytes through the atomic writer alone (a temporary file, every write checked, fsync,
// rename): what the DNG write adds to the encoding.
void BM_AtomicWrite4k(benchmark::State& state) {
  const std::vector<uint8_t> bytes(size_t(kWidth) * kHeight * 2, 7);
  const std::string path = scratch("obscura-bench.bin");
  for (auto _ : state) write_file_atomically(path, bytes);
  state.SetBytesProcessed(int64_t(state.iterations()) * kWidth * kHeight * 2);
  std::filesystem::remove(path);
}

// libtiff's own: TIFFOpen on the file, the same rows, no compression, one strip per 32 rows.
void BM_LibtiffRawWrite4k(benchmark::State& state) {
  const RawCapture capture = capture_raw(film_4k(), SensorSpec{}, bench::sensor_exposure(), 0);
  const std::string path = scratch("obscura-bench.tif");
  for (auto _ : state) {
    TIFF* t = TIFFOpen(path.c_str(), "w");
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
    TIFFClose(t);
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * kWidth * kHeight * 2);
  std::filesystem::remove(path);
}

BENCHMARK(BM_SensorCapture4k)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SensorDevelop4k)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DngWrite4k)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AtomicWrite4k)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LibtiffRawWrite4k)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

// The raw sensor benchmarks' input (bench/sensor_bench.cpp, bench/dng_write_compare.cpp): a 4K
// film of uniform noise and an exposure that puts a few thousand electrons in a mid-grey pixel.
#pragma once

#include "obscura/film/image.h"
#include "obscura/math/rng.h"
#include "obscura/sensor/sensor_capture.h"

namespace obscura::bench {

constexpr int kWidth = 3840, kHeight = 2160;

inline Image film_4k() {
  Image image(kWidth, kHeight, 3);
  Pcg32 rng(1);
  for (float& v : image.data) v = rng.next_float();
  return image;
}

inline SensorExposure sensor_exposure() {
  SensorExposure e;
  e.lux_seconds_per_film = 0.05;
  return e;
}

}  // namespace obscura::bench

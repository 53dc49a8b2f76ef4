#include "obscura/color/blue_noise.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/error.h"
#include "obscura/math/rng.h"

namespace obscura {

namespace {

// The pattern and its "energy": each pixel's sum of a Gaussian of its toroidal distance to every
// dot. The tightest cluster is the dot with the most energy; the largest void, the empty pixel
// with the least. Adding or removing a dot updates all energies with one table lookup each.
class Pattern {
 public:
  Pattern(int size) : n_(size), dots_(size_t(size) * size, 0), energy_(dots_.size(), 0.0) {
    constexpr double sigma = 1.5;  // Ulichney's recommended filter width
    kernel_.resize(dots_.size());
    for (int dy = 0; dy < n_; ++dy)
      for (int dx = 0; dx < n_; ++dx) {
        int wx = std::min(dx, n_ - dx), wy = std::min(dy, n_ - dy);
        kernel_[size_t(dy) * n_ + dx] = std::exp(-(wx * wx + wy * wy) / (2 * sigma * sigma));
      }
  }

  void set(size_t i, bool dot) {
    if (bool(dots_[i]) == dot) return;
    dots_[i] = dot;
    double sign = dot ? 1 : -1;
    int ix = int(i % n_), iy = int(i / n_);
    for (int y = 0; y < n_; ++y) {
      int dy = (y - iy + n_) % n_;
      for (int x = 0; x < n_; ++x) {
        int dx = (x - ix + n_) % n_;
        energy_[size_t(y) * n_ + x] += sign * kernel_[size_t(dy) * n_ + dx];
      }
    }
  }
  bool dot(size_t i) const { return dots_[i]; }

  // The dot with the highest energy, and the empty pixel with the lowest.
  size_t tightest_cluster() const { return extreme(true, true); }
  size_t largest_void() const { return extreme(false, false); }

 private:
  size_t extreme(bool value, bool highest) const {
    size_t best = dots_.size();
    for (size_t i = 0; i < dots_.size(); ++i) {
      if (bool(dots_[i]) != value) continue;
      if (best == dots_.size() ||
          (highest ? energy_[i] > energy_[best] : energy_[i] < energy_[best]))
        best = i;
    }
    return best;
  }

  int n_;
  std::vector<uint8_t> dots_;
  std::vector<double> energy_;
  std::vector<double> kernel_;
};

}  // namespace

BlueNoiseMask generate_blue_noise(int size, uint64_t seed) {
  if (size < 4 || size > 256) throw Error("blue noise", "mask size must be 4…256");
  const size_t count = size_t(size) * size;
  const size_t initial = std::max<size_t>(1, count / 10);

  // 1. A random initial pattern of ~10 % dots, relaxed by moving the tightest cluster into the
  //    largest void until that move would put the dot back where it came from.
  Pattern pattern(size);
  for (size_t placed = 0, k = 0; placed < initial; ++k) {
    size_t i = hash_words(seed, k) % count;
    if (!pattern.dot(i)) pattern.set(i, true), ++placed;
  }
  for (size_t guard = 0; guard < 4 * count; ++guard) {
    size_t cluster = pattern.tightest_cluster();
    pattern.set(cluster, false);
    size_t void_ = pattern.largest_void();
    pattern.set(void_, true);
    if (void_ == cluster) break;
  }

  BlueNoiseMask mask{size, std::vector<uint32_t>(count, 0)};
  std::vector<uint8_t> initial_dots(count);
  for (size_t i = 0; i < count; ++i) initial_dots[i] = pattern.dot(i);

  // 2. Rank the initial dots: remove tightest clusters one by one, highest rank first.
  {
    Pattern p = pattern;
    for (size_t rank = initial; rank-- > 0;) {
      size_t i = p.tightest_cluster();
      p.set(i, false);
      mask.ranks[i] = uint32_t(rank);
    }
  }
  // 3. Fill the rest: the next rank always goes to the largest void of the growing pattern.
  for (size_t rank = initial; rank < count; ++rank) {
    size_t i = pattern.largest_void();
    pattern.set(i, true);
    mask.ranks[i] = uint32_t(rank);
  }
  return mask;
}

const BlueNoiseMask& blue_noise_mask() {
  static const BlueNoiseMask mask = generate_blue_noise(64);
  return mask;
}

}  // namespace obscura

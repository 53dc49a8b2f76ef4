// The numbers one sample of one pixel draws, dimension after dimension: the renderers' only
// source of randomness. Every number is a pure function of (seed, pixel, sample index,
// dimension), so images do not depend on threads or the order pixels are rendered in.
//
//   kSobol        Owen-scrambled Sobol' points, "padded" (pbrt-v4, Burley 2020): each pair of
//                 dimensions takes Sobol dimensions 0 and 1 of the sample index, shuffled by a
//                 hash of (seed, pixel, pair) and Owen-scrambled per dimension. A pixel's first
//                 2^k samples of any pair are then a (0, k, 2)-net: one point in every
//                 elementary interval of area 2^−k. next_2d() starts a new pair; next_1d() uses
//                 the pair's components in turn.
//   kIndependent  Independent uniform numbers (a hash per dimension): the reference any
//                 low-discrepancy sampler must agree with in expectation.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "obscura/math/rng.h"
#include "obscura/math/sobol.h"
#include "obscura/math/vector.h"

namespace obscura {

enum class SamplerType { kSobol, kIndependent };

// "sobol", "independent"
std::string_view sampler_type_name(SamplerType type);
// The type of that name; nothing for any other name.
std::optional<SamplerType> parse_sampler_type(std::string_view name);

// The Sobol sampler's per-pair hashes of one (seed, pixel): the same for every sample of the pixel,
// so a render loop that takes a pixel's samples one after another keeps them here and each is
// computed once per pixel instead of once per sample. Filled on first use.
class SobolPixelKeys {
 public:
  static constexpr uint32_t kPairs = 32;  // the camera's and about ten path vertices'

  SobolPixelKeys(uint64_t seed, Point2i pixel)
      : seed_pixel_hash_(
            hash_words_first(seed, (uint64_t(uint32_t(pixel.y)) << 32) | uint32_t(pixel.x))) {}
  uint64_t seed_pixel_hash() const { return seed_pixel_hash_; }
  // hash_words(seed, pixel key, pair, 0x50b01u) and its mix_bits (component 1's scramble seed).
  struct Pair {
    uint64_t key, mixed;
  };
  static Pair compute(uint64_t seed_pixel_hash, uint32_t pair) {
    uint64_t key = hash_words_last(seed_pixel_hash, pair, 0x50b01u);
    return {key, mix_bits(key)};
  }
  Pair pair(uint32_t pair) {
    if (pair >= kPairs) return compute(seed_pixel_hash_, pair);
    const uint32_t bit = 1u << pair;
    if (!(filled_ & bit)) {
      pairs_[pair] = compute(seed_pixel_hash_, pair);
      filled_ |= bit;
    }
    return pairs_[pair];
  }

 private:
  uint64_t seed_pixel_hash_;
  uint32_t filled_ = 0;
  Pair pairs_[kPairs];
};

class Sampler {
 public:
  Sampler(SamplerType type, uint64_t seed, Point2i pixel, uint32_t sample_index)
      : type_(type), seed_(seed), pixel_(pixel), sample_index_(sample_index) {
    // Every pair's key hashes (seed, pixel, pair): mix the part common to all pairs once.
    if (type_ == SamplerType::kSobol) {
      uint64_t pixel_key = (uint64_t(uint32_t(pixel_.y)) << 32) | uint32_t(pixel_.x);
      seed_pixel_hash_ = hash_words_first(seed_, pixel_key);
    }
  }
  // The same numbers, with the pair hashes taken from `keys`, which must be those of this
  // (seed, pixel) and outlive the sampler.
  Sampler(SamplerType type, uint64_t seed, Point2i pixel, uint32_t sample_index,
          SobolPixelKeys& keys)
      : type_(type), seed_(seed), pixel_(pixel), sample_index_(sample_index), keys_(&keys) {
    seed_pixel_hash_ = keys.seed_pixel_hash();
  }

  float next_1d() {
    if (type_ == SamplerType::kIndependent)
      return sample_uniform(seed_, pixel_, sample_index_, dimension_++);
    uint32_t d = dimension_++;
    return sobol_component(d >> 1, int(d & 1));
  }
  Point2f next_2d() {
    if (type_ == SamplerType::kSobol) dimension_ += dimension_ & 1;  // start a fresh pair
    float u = next_1d();
    return {u, next_1d()};
  }
  // Pass over numbers nobody reads (a pinhole camera's lens point, the shutter time of a still
  // scene) without computing them: as every number depends only on its dimension, the numbers
  // drawn after are the same as if these had been drawn.
  void skip_1d() { ++dimension_; }
  void skip_2d() {
    if (type_ == SamplerType::kSobol) dimension_ += dimension_ & 1;
    dimension_ += 2;
  }
  uint32_t dimension() const { return dimension_; }

 private:
  float sobol_component(uint32_t pair, int component) {
    if (pair != pair_) {
      pair_ = pair;
      // hash_words(seed_, pixel key, pair, 0x50b01u), its first half mixed at construction.
      pair_keys_ = keys_ ? keys_->pair(pair) : SobolPixelKeys::compute(seed_pixel_hash_, pair);
      // Shuffle which Sobol point this sample gets: scrambling the index from its high bits
      // down maps the first 2^k indices onto an aligned block of 2^k, whose points form a net.
      pair_index_ = owen_scramble(sample_index_, uint32_t(pair_keys_.key));
    }
    // Component 0 is Sobol dimension 0 (van der Corput), scrambled without building the point.
    if (component == 0)
      return fraction_to_float(
          owen_scrambled_van_der_corput(pair_index_, uint32_t(pair_keys_.key >> 32)));
    return fraction_to_float(owen_scramble(sobol_bits(pair_index_, 1), uint32_t(pair_keys_.mixed)));
  }

  SamplerType type_;
  uint64_t seed_;
  Point2i pixel_;
  uint32_t sample_index_;
  uint32_t dimension_ = 0;
  // The current pair's hash and shuffled index, computed once for its two components.
  uint32_t pair_ = ~0u, pair_index_ = 0;
  SobolPixelKeys::Pair pair_keys_{};
  uint64_t seed_pixel_hash_ = 0;    // hash_words_first(seed, pixel), Sobol only
  SobolPixelKeys* keys_ = nullptr;  // the pixel's cached pair hashes, if given
};

}  // namespace obscura

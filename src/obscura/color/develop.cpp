#include "obscura/color/develop.h"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "obscura/color/blue_noise.h"
#include "obscura/color/color_space.h"
#include "obscura/color/display_kernel.h"
#include "obscura/math/error.h"

namespace obscura {

DevelopStats& DevelopStats::operator+=(const DevelopStats& o) {
  nan_pixels += o.nan_pixels;
  inf_pixels += o.inf_pixels;
  out_of_gamut_pixels += o.out_of_gamut_pixels;
  return *this;
}

namespace {

// The exact code of a display-linear value: quantize(transfer(v · scale)), in double.
uint32_t exact_code(const DisplaySpaceInfo& d, int bits, float v) {
  return quantize(encode(d.transfer, double(v) * d.linear_scale), bits);
}

// Linear thresholds between consecutive codes, and a table indexed by the top 16 bits of a
// positive float giving the code at the start of that float range. Within one such range (a
// 1/128 of an octave) the curves here rise by less than one code, so one comparison finishes
// the lookup; construction verifies that and reports `valid = false` otherwise.
struct CodeTable {
  bool valid = false;
  float top = 0;                  // the smallest value that gets the highest code
  std::vector<float> thresholds;  // thresholds[k]: smallest float with code ≥ k; [max+1] = ∞
  std::vector<uint16_t> bucket_code;

  CodeTable(const DisplaySpaceInfo& d, int bits) {
    const uint32_t max_code = (1u << bits) - 1;
    thresholds.assign(max_code + 2, std::numeric_limits<float>::infinity());
    thresholds[0] = 0;
    for (uint32_t k = 1; k <= max_code; ++k) {
      // Bisection over the bit patterns of positive floats, which are ordered like the values.
      uint32_t lo = 0, hi = std::bit_cast<uint32_t>(FLT_MAX);
      while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (exact_code(d, bits, std::bit_cast<float>(mid)) >= k)
          hi = mid;
        else
          lo = mid + 1;
      }
      thresholds[k] = std::bit_cast<float>(lo);
    }
    top = thresholds[max_code];
    uint32_t buckets = (std::bit_cast<uint32_t>(top) >> 16) + 1;
    bucket_code.resize(buckets);
    for (uint32_t b = 0; b < buckets; ++b) {
      uint32_t first = exact_code(d, bits, std::bit_cast<float>(b << 16));
      uint32_t last = exact_code(d, bits, std::bit_cast<float>((b << 16) | 0xFFFF));
      if (last > first + 1) return;  // more than one step inside: table not usable
      bucket_code[b] = uint16_t(first);
    }
    bucket_code.push_back(bucket_code.back());  // padding for 32-bit gathers (display_kernel)
    valid = true;
  }

  // v must be in [0, top] (not NaN).
  uint32_t code(float v) const {
    uint32_t c = bucket_code[std::bit_cast<uint32_t>(v) >> 16];
    return c + (v >= thresholds[c + 1]);
  }
};

// The transfer curve sampled at every 2¹⁵-th float (256 samples per octave), interpolated
// linearly: relative error below 1e-6, far below the noise a dither adds.
struct EncodeTable {
  std::vector<float> values, slopes;
  float top = 0;

  EncodeTable(const DisplaySpaceInfo& d, float top_) : top(top_) {
    uint32_t n = (std::bit_cast<uint32_t>(top) >> 15) + 2;
    values.resize(n + 1);
    for (uint32_t i = 0; i <= n; ++i)
      values[i] = float(encode(d.transfer, double(std::bit_cast<float>(i << 15)) * d.linear_scale));
    slopes.resize(n);
    for (uint32_t i = 0; i < n; ++i)
      slopes[i] = (values[i + 1] - values[i]) /
                  (std::bit_cast<float>((i + 1) << 15) - std::bit_cast<float>(i << 15));
  }
  float encode_value(float v) const {  // v in [0, top]
    uint32_t i = std::bit_cast<uint32_t>(v) >> 15;
    return values[i] + slopes[i] * (v - std::bit_cast<float>(i << 15));
  }
};

}  // namespace

struct DisplayEncoder::Impl {
  DisplaySettings settings;
  const DisplaySpaceInfo& display;
  ColorSpaceInfo display_space;
  float m[9];         // display linear from working linear (Rec.709)
  float white_limit;  // display-linear value of the full signal (1 for SDR)
  float gain;         // 2^EV
  uint32_t max_code;
  std::unique_ptr<CodeTable> codes;    // fast exact path
  std::unique_ptr<EncodeTable> curve;  // dithered path
  bool fast = false;
  bool simd = detail::has_avx2_kernel();
  bool simd_dither = false;         // the kernel's dithered mode applies (set in the constructor)
  int dither_period = 1;            // a power of two
  std::vector<float> dither_table;  // [channel][y mod period][x mod period]

  explicit Impl(const DisplaySettings& s)
      : settings(s),
        display(display_space_info(s.display)),
        display_space(color_space(display.color_space)) {
    validate(s);
    Matrix3d md = rgb_to_rgb_matrix(primaries::kRec709, display.primaries);
    for (int i = 0; i < 9; ++i) m[i] = float(md.m[i / 3][i % 3]);
    white_limit = float(decode(display.transfer, 1.0) / display.linear_scale);
    gain = std::exp2(s.exposure_ev);
    max_code = (1u << s.bits) - 1;
    bool simple_tone = s.tonemap.op == ToneMap::kNone || s.tonemap.op == ToneMap::kClamp;
    if (s.exposure_ev == 0 && simple_tone && s.gamut == GamutMapping::kClip && s.bits <= 8 &&
        s.dither == Dither::kNone) {
      codes = std::make_unique<CodeTable>(display, s.bits);
      fast = codes->valid;
    }
    if (s.dither != Dither::kNone) {
      curve = std::make_unique<EncodeTable>(display, white_limit);
      // The pattern's offsets for one period in x and y, per channel, read by encode_generic.
      dither_period = s.dither == Dither::kBayer ? 8 : blue_noise_mask().size;
      int p = dither_period;
      dither_table.resize(size_t(3) * p * p);
      for (int c = 0; c < 3; ++c)
        for (int y = 0; y < p; ++y)
          for (int x = 0; x < p; ++x)
            dither_table[(size_t(c) * p + y) * p + x] = dither_offset(s.dither, x, y, c);
      simd_dither = simd && s.exposure_ev == 0 && simple_tone && s.gamut == GamutMapping::kClip;
    }
  }

  // Replaces non-finite values with defined ones; counts the pixel once.
  static void sanitize(float& r, float& g, float& b, DevelopStats& stats) {
    if (std::isfinite(r) && std::isfinite(g) && std::isfinite(b)) [[likely]]
      return;
    bool nan = std::isnan(r) || std::isnan(g) || std::isnan(b);
    (nan ? stats.nan_pixels : stats.inf_pixels)++;
    for (float* c : {&r, &g, &b}) {
      if (std::isnan(*c))
        *c = 0;
      else if (std::isinf(*c))
        *c = 0;
    }
  }

  // Exposure, tone map and matrix: working linear → display linear.
  void to_display(float& r, float& g, float& b) const {
    if (gain != 1) r *= gain, g *= gain, b *= gain;
    if (settings.tonemap.op != ToneMap::kNone) {
      r = tone_map(r, settings.tonemap), g = tone_map(g, settings.tonemap);
      b = tone_map(b, settings.tonemap);
    }
    float x = m[0] * r + m[1] * g + m[2] * b;
    float y = m[3] * r + m[4] * g + m[5] * b;
    float z = m[6] * r + m[7] * g + m[8] * b;
    r = x, g = y, b = z;
  }

  static constexpr float kGamutTolerance = 1e-6f;
  bool out_of_gamut(float r, float g, float b) const {
    float hi = white_limit * (1 + kGamutTolerance);
    return std::min({r, g, b}) < -kGamutTolerance || std::max({r, g, b}) > hi;
  }

  template <typename Out>
  void encode_generic(const float* in, int count, int x0, int y, Out* out,
                      DevelopStats& stats) const {
    detail::CodeKernel kernel{m,
                              white_limit,
                              nullptr,
                              nullptr,
                              -kGamutTolerance,
                              white_limit * (1 + kGamutTolerance),
                              settings.tonemap.op == ToneMap::kClamp};
    if (curve) {
      kernel.curve_values = curve->values.data(), kernel.curve_slopes = curve->slopes.data();
      int p = dither_period;
      for (int c = 0; c < 3; ++c)
        kernel.dither_rows[c] = dither_table.data() + (size_t(c) * p + (y & (p - 1))) * p;
      kernel.dither_period = p, kernel.max_code = float(max_code);
    }
    for (int i = 0; i < count; ++i) {
      if (simd_dither) {
        size_t out_of_gamut = 0;
        i += detail::encode_blocks_avx2(kernel, in + 3 * i, count - i, x0 + i, out + 3 * i,
                                        out_of_gamut);
        stats.out_of_gamut_pixels += out_of_gamut;
        if (i >= count) break;
      }
      float c[3] = {in[3 * i], in[3 * i + 1], in[3 * i + 2]};
      sanitize(c[0], c[1], c[2], stats);
      to_display(c[0], c[1], c[2]);
      if (out_of_gamut(c[0], c[1], c[2])) {
        stats.out_of_gamut_pixels++;
        if (settings.gamut == GamutMapping::kCompress) compress(c);
      }
      for (int k = 0; k < 3; ++k) {
        float v = std::clamp(c[k], 0.f, white_limit);
        uint32_t q;
        if (fast) {
          q = codes->code(std::min(v, codes->top));
        } else if (curve) {
          int p = dither_period;
          float offset = dither_table[(size_t(k) * p + (y & (p - 1))) * p + ((x0 + i) & (p - 1))];
          float level = std::floor(curve->encode_value(v) * float(max_code) + 0.5f + offset);
          q = uint32_t(std::clamp(level, 0.f, float(max_code)));
        } else {
          q = quantize(obscura::encode(display.transfer, double(v) * display.linear_scale),
                       settings.bits);
        }
        out[3 * i + k] = Out(q);
      }
    }
  }

  // CSS Color 4 chroma reduction, on the display's encoded values.
  void compress(float* c) const {
    Vec3d e;
    for (int k = 0; k < 3; ++k)
      e[k] =
          obscura::encode(display.transfer, double(std::max(c[k], -1e30f)) * display.linear_scale);
    Vec3d mapped = gamut_map_css(e, display_space);
    for (int k = 0; k < 3; ++k)
      c[k] = float(decode(display.transfer, mapped[k]) / display.linear_scale);
  }

  // The fast path: clamp (optional), matrix, table lookup; blocks of 8 pixels go through the
  // AVX2 kernel where the CPU has it, the rest (tails, non-finite pixels) through this loop,
  // which computes bit-identical results.
  template <bool kClamp, typename Out>
  void encode_fast(const float* in, int count, int x0, Out* out, DevelopStats& stats) const {
    const float top = codes->top;
    const float* thresholds = codes->thresholds.data();
    const uint16_t* bucket = codes->bucket_code.data();
    size_t out_of_gamut = 0;
    detail::CodeKernel kernel{
        m, top, thresholds, bucket, -kGamutTolerance, white_limit * (1 + kGamutTolerance), kClamp};
    for (int i = 0; i < count;) {
      if (simd) {
        int done = detail::encode_blocks_avx2(kernel, in + 3 * i, count - i, x0 + i, out + 3 * i,
                                              out_of_gamut);
        i += done;
        if (i >= count) break;
      }
      float r = in[3 * i], g = in[3 * i + 1], b = in[3 * i + 2];
      sanitize(r, g, b, stats);
      if (kClamp) r = std::min(r, 1.f), g = std::min(g, 1.f), b = std::min(b, 1.f);
      float d[3] = {m[0] * r + m[1] * g + m[2] * b, m[3] * r + m[4] * g + m[5] * b,
                    m[6] * r + m[7] * g + m[8] * b};
      out_of_gamut += out_of_gamut_fast(d);
      for (int k = 0; k < 3; ++k) {
        float v = std::min(std::max(d[k], 0.f), top);
        uint32_t c = bucket[std::bit_cast<uint32_t>(v) >> 16];
        out[3 * i + k] = Out(c + (v >= thresholds[c + 1]));
      }
      ++i;
    }
    stats.out_of_gamut_pixels += out_of_gamut;
  }

  bool out_of_gamut_fast(const float* d) const { return out_of_gamut(d[0], d[1], d[2]); }

  template <typename Out>
  void encode(const float* in, int count, int x0, int y, Out* out, DevelopStats& stats) const {
    if (fast && settings.tonemap.op == ToneMap::kNone)
      encode_fast<false>(in, count, x0, out, stats);
    else if (fast)
      encode_fast<true>(in, count, x0, out, stats);
    else
      encode_generic(in, count, x0, y, out, stats);
  }
};

DisplayEncoder::DisplayEncoder(const DisplaySettings& s) : impl_(std::make_unique<Impl>(s)) {}
DisplayEncoder::~DisplayEncoder() = default;
bool DisplayEncoder::uses_fast_path() const {
  return impl_->fast;
}

bool DisplayEncoder::out_of_gamut(Rgb c) const {
  DevelopStats ignored;
  Impl::sanitize(c.r, c.g, c.b, ignored);
  impl_->to_display(c.r, c.g, c.b);
  return impl_->out_of_gamut(c.r, c.g, c.b);
}

void DisplayEncoder::encode_rgb_row(const float* rgb, int count, int x0, int y, uint8_t* out,
                                    DevelopStats& stats) const {
  if (impl_->settings.bits > 8) throw Error("display encoder", "8-bit output needs bits ≤ 8");
  impl_->encode(rgb, count, x0, y, out, stats);
}

void DisplayEncoder::encode_rgb_row(const float* rgb, int count, int x0, int y, uint16_t* out,
                                    DevelopStats& stats) const {
  impl_->encode(rgb, count, x0, y, out, stats);
}

namespace {

void check_pixels(const LinearPixels& image) {
  if (image.width <= 0 || image.height <= 0 || !image.data ||
      (image.channels != 1 && image.channels != 3 && image.channels != 4))
    throw Error("develop", "expected a non-empty image with 1, 3 or 4 channels; got " +
                               std::to_string(image.width) + "x" + std::to_string(image.height) +
                               "x" + std::to_string(image.channels));
}

// One row as packed RGB floats (grey expanded, alpha dropped).
void load_rgb_row(const LinearPixels& image, int y, std::vector<float>& rgb) {
  rgb.resize(size_t(image.width) * 3);
  const float* row = image.data + size_t(y) * image.width * image.channels;
  for (int x = 0; x < image.width; ++x)
    for (int k = 0; k < 3; ++k)
      rgb[3 * x + k] = row[x * image.channels + (image.channels == 1 ? 0 : k)];
}

}  // namespace

DisplayImage develop(const LinearPixels& image, const DisplaySettings& settings) {
  check_pixels(image);
  DisplayEncoder encoder(settings);
  DisplayImage out;
  out.width = image.width, out.height = image.height;
  out.channels = image.channels == 4 ? 4 : 3;
  out.bits = settings.bits, out.display = settings.display;
  out.codes.resize(size_t(out.width) * out.height * out.channels);
  tbb::combinable<DevelopStats> stats;
  tbb::parallel_for(
      tbb::blocked_range<int>(0, image.height), [&](const tbb::blocked_range<int>& rows) {
        std::vector<float> rgb;
        std::vector<uint16_t> codes(size_t(image.width) * 3);
        DevelopStats& local = stats.local();
        for (int y = rows.begin(); y < rows.end(); ++y) {
          load_rgb_row(image, y, rgb);
          uint16_t* dst = out.codes.data() + size_t(y) * image.width * out.channels;
          if (out.channels == 3) {
            encoder.encode_rgb_row(rgb.data(), image.width, 0, y, dst, local);
            continue;
          }
          encoder.encode_rgb_row(rgb.data(), image.width, 0, y, codes.data(), local);
          const float* row = image.data + size_t(y) * image.width * 4;
          for (int x = 0; x < image.width; ++x) {
            for (int k = 0; k < 3; ++k) dst[4 * x + k] = codes[3 * x + k];
            dst[4 * x + 3] = uint16_t(quantize(row[4 * x + 3], settings.bits));  // NaN → 0
          }
        }
      });
  stats.combine_each([&](const DevelopStats& s) { out.stats += s; });
  return out;
}

std::vector<uint8_t> out_of_gamut_mask(const LinearPixels& image, const DisplaySettings& settings) {
  check_pixels(image);
  DisplaySettings s = settings;
  s.dither = Dither::kNone;
  DisplayEncoder encoder(s);
  std::vector<uint8_t> mask(size_t(image.width) * image.height);
  std::vector<float> rgb;
  for (int y = 0; y < image.height; ++y) {
    load_rgb_row(image, y, rgb);
    for (int x = 0; x < image.width; ++x)
      mask[size_t(y) * image.width + x] =
          encoder.out_of_gamut({rgb[3 * x], rgb[3 * x + 1], rgb[3 * x + 2]});
  }
  return mask;
}

}  // namespace obscura

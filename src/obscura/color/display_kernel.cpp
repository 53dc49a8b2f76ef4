#include "obscura/color/display_kernel.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define OBSCURA_HAS_X86 1
#endif

namespace obscura::detail {

#if OBSCURA_HAS_X86

bool has_avx2_kernel() {
  return __builtin_cpu_supports("avx2");
}

namespace {

// 8 packed RGB pixels → three vectors r, g, b (lanes in pixel order).
__attribute__((target("avx2"))) inline void load_rgb8(const float* p, __m256& r, __m256& g,
                                                      __m256& b) {
  __m256 m03 = _mm256_castps128_ps256(_mm_loadu_ps(p + 0));  // r0 g0 b0 r1 | r4 g4 b4 r5
  __m256 m14 = _mm256_castps128_ps256(_mm_loadu_ps(p + 4));  // g1 b1 r2 g2 | g5 b5 r6 g6
  __m256 m25 = _mm256_castps128_ps256(_mm_loadu_ps(p + 8));  // b2 r3 g3 b3 | b6 r7 g7 b7
  m03 = _mm256_insertf128_ps(m03, _mm_loadu_ps(p + 12), 1);
  m14 = _mm256_insertf128_ps(m14, _mm_loadu_ps(p + 16), 1);
  m25 = _mm256_insertf128_ps(m25, _mm_loadu_ps(p + 20), 1);
  __m256 xy = _mm256_shuffle_ps(m14, m25, _MM_SHUFFLE(2, 1, 3, 2));  // r2 g2 r3 g3
  __m256 yz = _mm256_shuffle_ps(m03, m14, _MM_SHUFFLE(1, 0, 2, 1));  // g0 b0 g1 b1
  r = _mm256_shuffle_ps(m03, xy, _MM_SHUFFLE(2, 0, 3, 0));
  g = _mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
  b = _mm256_shuffle_ps(yz, m25, _MM_SHUFFLE(3, 0, 3, 1));
}

// One channel's codes: clamp, bucket of the top 16 bits, one threshold comparison.
__attribute__((target("avx2"))) inline __m256i codes_of(const CodeKernel& k, __m256 v) {
  v = _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(k.top));
  __m256i index = _mm256_srli_epi32(_mm256_castps_si256(v), 16);
  // 16-bit entries gathered as 32-bit words at a 2-byte stride; the padding entry keeps the
  // last read inside the table.
  __m256i code =
      _mm256_and_si256(_mm256_i32gather_epi32(reinterpret_cast<const int*>(k.buckets), index, 2),
                       _mm256_set1_epi32(0xFFFF));
  __m256 next = _mm256_i32gather_ps(k.thresholds + 1, code, 4);
  __m256i step = _mm256_castps_si256(_mm256_cmp_ps(v, next, _CMP_GE_OQ));
  return _mm256_sub_epi32(code, step);  // step is −1 where the value reaches the next code
}

// Dithered codes: the interpolated curve, scaled, plus the pattern's offsets, floored.
__attribute__((target("avx2"))) inline __m256i dithered_codes_of(const CodeKernel& k, __m256 v,
                                                                 const float* offsets) {
  v = _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(k.top));
  __m256i index = _mm256_srli_epi32(_mm256_castps_si256(v), 15);
  __m256 start = _mm256_castsi256_ps(_mm256_slli_epi32(index, 15));
  __m256 value = _mm256_i32gather_ps(k.curve_values, index, 4);
  __m256 slope = _mm256_i32gather_ps(k.curve_slopes, index, 4);
  __m256 e = _mm256_add_ps(value, _mm256_mul_ps(slope, _mm256_sub_ps(v, start)));
  __m256 level = _mm256_add_ps(
      _mm256_add_ps(_mm256_mul_ps(e, _mm256_set1_ps(k.max_code)), _mm256_set1_ps(0.5f)),
      _mm256_loadu_ps(offsets));
  level = _mm256_min_ps(_mm256_max_ps(_mm256_floor_ps(level), _mm256_setzero_ps()),
                        _mm256_set1_ps(k.max_code));
  return _mm256_cvttps_epi32(level);
}

__attribute__((target("avx2"))) inline bool all_finite(__m256 r, __m256 g, __m256 b) {
  __m256 exponent = _mm256_castsi256_ps(_mm256_set1_epi32(0x7F800000));
  __m256 any = _mm256_or_ps(_mm256_cmp_ps(_mm256_and_ps(r, exponent), exponent, _CMP_EQ_OQ),
                            _mm256_cmp_ps(_mm256_and_ps(g, exponent), exponent, _CMP_EQ_OQ));
  any = _mm256_or_ps(any, _mm256_cmp_ps(_mm256_and_ps(b, exponent), exponent, _CMP_EQ_OQ));
  return _mm256_movemask_ps(any) == 0;
}

template <typename Out>
__attribute__((target("avx2"))) int encode_blocks(const CodeKernel& k, const float* in, int count,
                                                  int x0, Out* out, size_t& out_of_gamut) {
  // Dither offsets are read 8 at a time from a row of the pattern: start on a multiple of 8.
  const bool dither = k.curve_values != nullptr;
  if (dither && x0 % 8 != 0) return 0;
  // 8-bit output is stored with two overlapping 16-byte writes per block, which spill 4 bytes
  // into the next pixels: keep two pixels of room after every block.
  const int room = sizeof(Out) == 1 ? 2 : 0;
  const __m256 m0 = _mm256_set1_ps(k.m[0]), m1 = _mm256_set1_ps(k.m[1]),
               m2 = _mm256_set1_ps(k.m[2]);
  const __m256 m3 = _mm256_set1_ps(k.m[3]), m4 = _mm256_set1_ps(k.m[4]),
               m5 = _mm256_set1_ps(k.m[5]);
  const __m256 m6 = _mm256_set1_ps(k.m[6]), m7 = _mm256_set1_ps(k.m[7]),
               m8 = _mm256_set1_ps(k.m[8]);
  const __m256 low = _mm256_set1_ps(k.gamut_low), high = _mm256_set1_ps(k.gamut_high);
  const __m256 one = _mm256_set1_ps(1.f);
  int i = 0;
  for (; i + 8 + room <= count; i += 8) {
    __m256 r, g, b;
    load_rgb8(in + 3 * i, r, g, b);
    if (!all_finite(r, g, b)) break;
    if (k.clamp_input)
      r = _mm256_min_ps(r, one), g = _mm256_min_ps(g, one), b = _mm256_min_ps(b, one);
    // Same operation order as the scalar path (no fused multiply-add), so results are identical.
    __m256 x = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(m0, r), _mm256_mul_ps(m1, g)),
                             _mm256_mul_ps(m2, b));
    __m256 y = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(m3, r), _mm256_mul_ps(m4, g)),
                             _mm256_mul_ps(m5, b));
    __m256 z = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(m6, r), _mm256_mul_ps(m7, g)),
                             _mm256_mul_ps(m8, b));
    __m256 outside =
        _mm256_or_ps(_mm256_cmp_ps(_mm256_min_ps(_mm256_min_ps(x, y), z), low, _CMP_LT_OQ),
                     _mm256_cmp_ps(_mm256_max_ps(_mm256_max_ps(x, y), z), high, _CMP_GT_OQ));
    out_of_gamut += __builtin_popcount(_mm256_movemask_ps(outside));
    __m256i cr, cg, cb;
    if (dither) {
      int column = (x0 + i) & (k.dither_period - 1);
      cr = dithered_codes_of(k, x, k.dither_rows[0] + column);
      cg = dithered_codes_of(k, y, k.dither_rows[1] + column);
      cb = dithered_codes_of(k, z, k.dither_rows[2] + column);
    } else {
      cr = codes_of(k, x), cg = codes_of(k, y), cb = codes_of(k, z);
    }
    if constexpr (sizeof(Out) == 1) {
      // Pack r | g << 8 | b << 16 per pixel, squeeze each 128-bit half to 12 bytes, store.
      __m256i packed =
          _mm256_or_si256(cr, _mm256_or_si256(_mm256_slli_epi32(cg, 8), _mm256_slli_epi32(cb, 16)));
      const __m256i squeeze =
          _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1, 0, 1, 2, 4, 5, 6,
                           8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
      packed = _mm256_shuffle_epi8(packed, squeeze);
      uint8_t* o = reinterpret_cast<uint8_t*>(out + 3 * i);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(o), _mm256_castsi256_si128(packed));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(o + 12), _mm256_extracti128_si256(packed, 1));
    } else {
      alignas(32) int32_t c[3][8];
      _mm256_store_si256(reinterpret_cast<__m256i*>(c[0]), cr);
      _mm256_store_si256(reinterpret_cast<__m256i*>(c[1]), cg);
      _mm256_store_si256(reinterpret_cast<__m256i*>(c[2]), cb);
      for (int p = 0; p < 8; ++p)
        for (int ch = 0; ch < 3; ++ch) out[3 * (i + p) + ch] = Out(c[ch][p]);
    }
  }
  return i;
}

}  // namespace

int encode_blocks_avx2(const CodeKernel& k, const float* in, int count, int x, uint8_t* out,
                       size_t& out_of_gamut) {
  return encode_blocks(k, in, count, x, out, out_of_gamut);
}
int encode_blocks_avx2(const CodeKernel& k, const float* in, int count, int x, uint16_t* out,
                       size_t& out_of_gamut) {
  return encode_blocks(k, in, count, x, out, out_of_gamut);
}

#else

bool has_avx2_kernel() {
  return false;
}
int encode_blocks_avx2(const CodeKernel&, const float*, int, int, uint8_t*, size_t&) {
  return 0;
}
int encode_blocks_avx2(const CodeKernel&, const float*, int, int, uint16_t*, size_t&) {
  return 0;
}

#endif

}  // namespace obscura::detail

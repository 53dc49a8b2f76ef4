#include "obscura/math/sobol.h"

#include <array>

namespace obscura {

namespace {

// Rows d = 2 … 10 of Joe and Kuo's new-joe-kuo-6.21201 table: degree s of the primitive
// polynomial, its inner coefficients a (bit j is the coefficient of x^(s−1−j)), and the initial
// direction numbers m₁ … m_s (odd, m_k < 2^k).
struct JoeKuoRow {
  int s;
  uint32_t a;
  std::array<uint32_t, 5> m;
};
constexpr std::array<JoeKuoRow, kSobolDimensions - 1> kJoeKuo = {{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
}};

using DirectionNumbers = std::array<std::array<uint32_t, 32>, kSobolDimensions>;

// v_k = m_k / 2^k as 32-bit fractions; beyond the initial numbers, Bratley and Fox's recurrence
// v_k = a₁v_{k−1} ⊕ … ⊕ a_{s−1}v_{k−s+1} ⊕ v_{k−s} ⊕ (v_{k−s} >> s).
constexpr DirectionNumbers make_direction_numbers() {
  DirectionNumbers v{};
  for (int k = 0; k < 32; ++k) v[0][k] = 1u << (31 - k);  // van der Corput
  for (int d = 1; d < kSobolDimensions; ++d) {
    const JoeKuoRow& row = kJoeKuo[d - 1];
    for (int k = 0; k < 32; ++k) {
      if (k < row.s) {
        v[d][k] = row.m[k] << (31 - k);
        continue;
      }
      uint32_t value = v[d][k - row.s] ^ (v[d][k - row.s] >> row.s);
      for (int j = 1; j < row.s; ++j)
        if ((row.a >> (row.s - 1 - j)) & 1) value ^= v[d][k - j];
      v[d][k] = value;
    }
  }
  return v;
}

// A point is the XOR of the direction numbers of the index's set bits, which is linear over
// GF(2): tabulate the XOR for every value of each of the index's four bytes.
using ByteTables = std::array<std::array<std::array<uint32_t, 256>, 4>, kSobolDimensions>;

constexpr ByteTables make_byte_tables() {
  DirectionNumbers v = make_direction_numbers();
  ByteTables t{};
  for (int d = 0; d < kSobolDimensions; ++d)
    for (int byte = 0; byte < 4; ++byte)
      for (uint32_t value = 0; value < 256; ++value) {
        uint32_t x = 0;
        for (int bit = 0; bit < 8; ++bit)
          if ((value >> bit) & 1) x ^= v[d][8 * byte + bit];
        t[d][byte][value] = x;
      }
  return t;
}

constexpr ByteTables kTables = make_byte_tables();

}  // namespace

uint32_t sobol_bits(uint32_t index, int dimension) {
  const auto& t = kTables[dimension];
  return t[0][index & 0xff] ^ t[1][(index >> 8) & 0xff] ^ t[2][(index >> 16) & 0xff] ^
         t[3][index >> 24];
}

}  // namespace obscura

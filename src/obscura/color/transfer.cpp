#include "obscura/color/transfer.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// BT.2020 Table 4: α and β solve the continuity of value and slope between the linear segment
// and the power law; BT.709's 1.099 and 0.018 are these rounded.
constexpr double kBt709Alpha = 1.09929682680944;
constexpr double kBt709Beta = 0.018053968510807;

// SMPTE ST 2084 constants, as the exact rationals the standard gives.
constexpr double kPqM1 = 2610.0 / 16384;
constexpr double kPqM2 = 2523.0 / 4096 * 128;
constexpr double kPqC1 = 3424.0 / 4096;
constexpr double kPqC2 = 2413.0 / 4096 * 32;
constexpr double kPqC3 = 2392.0 / 4096 * 32;

// ITU-R BT.2100 HLG constants.
constexpr double kHlgA = 0.17883277;
constexpr double kHlgB = 0.28466892;  // 1 − 4a
constexpr double kHlgC = 0.55991073;  // 0.5 − a·ln(4a)

double encode_positive(TransferFunction f, double v) {
  switch (f) {
    case TransferFunction::kLinear:
      return v;
    case TransferFunction::kSrgb:
      return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    case TransferFunction::kBt709:
      return v < kBt709Beta ? 4.5 * v : kBt709Alpha * std::pow(v, 0.45) - (kBt709Alpha - 1);
    case TransferFunction::kBt1886:
      return std::pow(v, 1 / 2.4);
    case TransferFunction::kGamma22:
      return std::pow(v, 1 / 2.2);
    case TransferFunction::kPq: {
      double p = std::pow(v, kPqM1);
      return std::pow((kPqC1 + kPqC2 * p) / (1 + kPqC3 * p), kPqM2);
    }
    case TransferFunction::kHlg:
      return v <= 1.0 / 12 ? std::sqrt(3 * v) : kHlgA * std::log(12 * v - kHlgB) + kHlgC;
  }
  return v;
}

double decode_positive(TransferFunction f, double e) {
  switch (f) {
    case TransferFunction::kLinear:
      return e;
    case TransferFunction::kSrgb:
      return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
    case TransferFunction::kBt709:
      return e < 4.5 * kBt709Beta ? e / 4.5
                                  : std::pow((e + kBt709Alpha - 1) / kBt709Alpha, 1 / 0.45);
    case TransferFunction::kBt1886:
      return std::pow(e, 2.4);
    case TransferFunction::kGamma22:
      return std::pow(e, 2.2);
    case TransferFunction::kPq: {
      // The PQ signal saturates at (c2/c3)^m2 ≈ 2.0 (infinite luminance); beyond it there is no
      // inverse, so the largest finite value stands in.
      double p = std::pow(e, 1 / kPqM2);
      double denominator = kPqC2 - kPqC3 * p;
      if (denominator <= 0) return HUGE_VAL;
      return std::pow(std::max(p - kPqC1, 0.0) / denominator, 1 / kPqM1);
    }
    case TransferFunction::kHlg:
      return e <= 0.5 ? e * e / 3 : (std::exp((e - kHlgC) / kHlgA) + kHlgB) / 12;
  }
  return e;
}

}  // namespace

double encode(TransferFunction f, double linear) {
  return std::copysign(encode_positive(f, std::abs(linear)), linear);
}

double decode(TransferFunction f, double encoded) {
  return std::copysign(decode_positive(f, std::abs(encoded)), encoded);
}

float encode(TransferFunction f, float linear) {
  return float(encode(f, double(linear)));
}
float decode(TransferFunction f, float encoded) {
  return float(decode(f, double(encoded)));
}

std::string transfer_function_name(TransferFunction f) {
  switch (f) {
    case TransferFunction::kLinear:
      return "linear";
    case TransferFunction::kSrgb:
      return "srgb";
    case TransferFunction::kBt709:
      return "bt709";
    case TransferFunction::kBt1886:
      return "bt1886";
    case TransferFunction::kGamma22:
      return "gamma2.2";
    case TransferFunction::kPq:
      return "pq";
    case TransferFunction::kHlg:
      return "hlg";
  }
  return "?";
}

TransferFunction parse_transfer_function(const std::string& name) {
  for (TransferFunction f :
       {TransferFunction::kLinear, TransferFunction::kSrgb, TransferFunction::kBt709,
        TransferFunction::kBt1886, TransferFunction::kGamma22, TransferFunction::kPq,
        TransferFunction::kHlg})
    if (transfer_function_name(f) == name) return f;
  throw Error(
      "transfer function",
      "unknown name '" + name + "'; expected linear, srgb, bt709, bt1886, gamma2.2, pq or hlg");
}

}  // namespace obscura

// Transfer functions: how linear light becomes a signal (encode) and back (decode).
//
// Each pair is an exact inverse over the whole real line: negative values are handled by odd
// symmetry (sign(v)·f(|v|)), values above 1 follow the same formula (sRGB, BT.709, gamma) or the
// standard's own extension (PQ above 10 000 cd/m², HLG above nominal peak), so that out-of-gamut
// and HDR values survive a round trip.
#pragma once

#include <string>

namespace obscura {

enum class TransferFunction {
  kLinear,
  kSrgb,     // IEC 61966-2-1 piecewise curve (sRGB, Display P3)
  kBt709,    // ITU-R BT.709 / BT.2020 OETF (4.5 L below β, α L^0.45 − (α − 1) above)
  kBt1886,   // ITU-R BT.1886 EOTF with black level 0: a pure 2.4 power
  kGamma22,  // pure 2.2 power
  kPq,       // SMPTE ST 2084 (BT.2100 PQ); linear 1 = 10 000 cd/m²
  kHlg,      // ITU-R BT.2100 HLG OETF; linear 1 = nominal peak scene light
};

// Linear → encoded signal, and its inverse.
double encode(TransferFunction f, double linear);
double decode(TransferFunction f, double encoded);
float encode(TransferFunction f, float linear);
float decode(TransferFunction f, float encoded);

// The name used on the command line and in docs ("srgb", "bt709", "bt1886", "gamma2.2", "pq",
// "hlg", "linear"), and back; parse throws obscura::Error listing the known names.
std::string transfer_function_name(TransferFunction f);
TransferFunction parse_transfer_function(const std::string& name);

}  // namespace obscura

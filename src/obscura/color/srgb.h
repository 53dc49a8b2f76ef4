// The sRGB transfer function (IEC 61966-2-1): encoding linear light for 8-bit displays and files.
// Shorthands for encode/decode(TransferFunction::kSrgb, …) in transfer.h.
#pragma once

namespace obscura {

// Linear [0, 1] → encoded [0, 1]; values outside [0, 1] are extended by odd symmetry / the power
// law so that the pair stays exact inverses.
float srgb_encode(float linear);
float srgb_decode(float encoded);

}  // namespace obscura

#include "obscura/color/srgb.h"

#include "obscura/color/transfer.h"

namespace obscura {

float srgb_encode(float linear) {
  return encode(TransferFunction::kSrgb, linear);
}

float srgb_decode(float encoded) {
  return decode(TransferFunction::kSrgb, encoded);
}

}  // namespace obscura

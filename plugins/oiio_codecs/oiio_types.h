// SampleType ↔ OpenImageIO's TypeDesc.
#pragma once

#include <OpenImageIO/typedesc.h>

#include "obscura/io/image_codecs.h"

namespace obscura::oiio {

inline OIIO::TypeDesc type_desc(SampleType type) {
  switch (type) {
    case SampleType::kUint8:
      return OIIO::TypeDesc::UINT8;
    case SampleType::kUint16:
      return OIIO::TypeDesc::UINT16;
    case SampleType::kHalf:
      return OIIO::TypeDesc::HALF;
    case SampleType::kFloat:
    case SampleType::kOther:
      break;
  }
  return OIIO::TypeDesc::FLOAT;
}

inline SampleType sample_type(OIIO::TypeDesc type) {
  if (type == OIIO::TypeDesc::UINT8) return SampleType::kUint8;
  if (type == OIIO::TypeDesc::UINT16) return SampleType::kUint16;
  if (type == OIIO::TypeDesc::HALF) return SampleType::kHalf;
  if (type == OIIO::TypeDesc::FLOAT) return SampleType::kFloat;
  return SampleType::kOther;
}

}  // namespace obscura::oiio

// DNG (Adobe Digital Negative 1.4) through libtiff: a CFA mosaic (one channel, 16-bit,
// PhotometricInterpretation CFA with CFARepeatPatternDim and CFAPattern), a monochrome image (one
// channel without a CFAPattern, LinearRaw) or a demosaiced linear raw image (three channels,
// LinearRaw), with the DNG tags a raw developer needs, read from the request's attributes by
// their DNG names:
//   "CFAPattern"               text "RGGB", "BGGR", "GRBG" or "GBRG" (CFA images)
//   "BlackLevel"               floats {black}
//   "WhiteLevel"               int
//   "ColorMatrix1", "ColorMatrix2"              floats, 3 per colour plane (XYZ → camera)
//   "CalibrationIlluminant1", "CalibrationIlluminant2"   int (EXIF LightSource: 21 D65, 17 A)
//   "AsShotNeutral"            floats, 1 per colour plane
//   "BaselineExposure"         floats {EV}
//   "Make", "Model", "UniqueCameraModel", "Software", "ImageDescription", "DateTime"  text
// Uncompressed, as most raw developers read every DNG that way.
#pragma once

#include <vector>

#include "obscura/io/image_codecs.h"

namespace obscura::codecs {

std::vector<unsigned char> encode_dng(const EncodeRequest& request);

}  // namespace obscura::codecs

// A reference image pipeline from the raw mosaic back to the film's units: black level and gain
// removed, demosaicing, white balance and the colour-correction matrix, giving linear Rec.709
// that the usual tone mapping and display encoding (color/develop.h) then write.
#pragma once

#include <string_view>

#include "obscura/film/image.h"
#include "obscura/sensor/sensor_capture.h"

namespace obscura {

enum class DemosaicMethod {
  kBilinear,  // each missing colour the mean of its nearest same-colour neighbours
  kMalvar,    // Malvar, He & Cutler 2004: bilinear corrected by the Laplacian of the known colour
};
DemosaicMethod parse_demosaic_method(std::string_view text);  // "bilinear" or "malvar"

// Camera RGB per pixel (three channels, the mosaic's values with the known one kept) from a
// one-channel mosaic under `cfa`; a monochrome mosaic is copied to all three. Edges mirror.
Image demosaic(const Image& mosaic, CfaPattern cfa, DemosaicMethod method);

// The capture developed: (raw − black) / K (electrons), demosaiced, divided by the D65 neutral
// (white balance), then the colour-correction matrix (camera → Rec.709, the inverse of the
// sensor's projection with the neutral put back) and divided by the electrons a film value of 1
// gives — so an unclipped, noiseless capture develops back to the film it was made from.
Image develop_raw(const RawCapture& capture, DemosaicMethod method);

}  // namespace obscura

// Writing a raw capture (sensor/sensor_capture.h) as a DNG a raw developer opens — the CFA
// mosaic, or a demosaiced linear raw image — with its ground truth beside it as OpenEXR:
//   x.dng             the DNG (Make "Obscura", the CFA pattern, black and white levels, colour
//                     matrices for D65 and illuminant A, the as-shot neutral, baseline exposure)
//   x.raw.exr         the mosaic's DN as floats ("raw")
//   x.irradiance.exr  the focal-plane irradiance in lux (R, G, B as the film's channels)
//   x.electrons.exr   the expected photoelectrons per pixel, without noise ("electrons")
// All files are written as every output is (io/atomic_file.h), in one transaction: either all
// of them are replaced or none is, and a full disk keeps the old files.
#pragma once

#include <string>
#include <vector>

#include "obscura/io/image_io.h"
#include "obscura/sensor/isp.h"
#include "obscura/sensor/sensor_capture.h"

namespace obscura {

struct DngWriteOptions {
  bool linear = false;  // demosaic first and write LinearRaw (three channels) instead of CFA
  DemosaicMethod demosaic = DemosaicMethod::kMalvar;
  bool ground_truth = true;  // the three EXR files beside the DNG
  std::string model = "Raw sensor";
  ImageMetadata metadata;  // the description; attributes are written to the EXR files only
};

// The ground-truth files beside `dng_path`, in the order above (without the DNG itself).
std::vector<std::string> sensor_ground_truth_paths(const std::string& dng_path);

// The DNG's BaselineExposure: the EV that brings a film value of 1 to the DNG's white, so a
// developer shows the render's exposure: log2((white − black) / (K · electrons per film unit)).
double dng_baseline_exposure(const RawCapture& capture);

// Writes the DNG (and the ground truth); returns every path written, the DNG first. Throws
// obscura::Error naming the file that could not be written (nothing is replaced then).
std::vector<std::string> write_dng(const std::string& path, const RawCapture& capture,
                                   const DngWriteOptions& options = {});

}  // namespace obscura

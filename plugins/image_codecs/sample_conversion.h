// Converting pixel values between the sample types of image_codecs.h, with OpenImageIO's rules
// (which the files and tests were made with): integers map to [0, 1] by their largest value,
// and floats map back clamped to [0, 1] and rounded to the nearest code.
#pragma once

#include <cstddef>

#include "obscura/io/image_codecs.h"

namespace obscura::codecs {

// Bytes per value of `type` (kOther: 0).
size_t sample_size(SampleType type);

// Converts `count` values from `from` to `to`; the buffers do not overlap.
void convert_samples(SampleType from, const void* in, SampleType to, void* out, size_t count);

// Copies pixels of `stored_channels` values each to pixels of the first `channels` of them,
// converting `from` to `to`.
void convert_pixels(SampleType from, const void* in, int stored_channels, SampleType to, void* out,
                    int channels, size_t pixel_count);

}  // namespace obscura::codecs

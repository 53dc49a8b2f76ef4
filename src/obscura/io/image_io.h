// Reading and writing image files through OpenImageIO.
//
// The format follows the file's extension: .png (8-bit, sRGB-encoded), .exr (linear 32-bit float),
// .pfm (linear 32-bit float). Files are written to a temporary name beside the target and renamed
// when complete, so a failed or interrupted write never leaves a partial file behind.
#pragma once

#include <string>

#include "obscura/film/image.h"

namespace obscura {

enum class ImageFormat { kPng, kExr, kPfm };

// The format for a path's extension (case-insensitive); throws obscura::Error naming the
// extension and the supported ones otherwise.
ImageFormat image_format_for_path(const std::string& path);

// Checks before any work is done that `path` can be written: a supported extension, not a
// directory, and a parent directory that exists and is writable. Throws obscura::Error.
void check_output_path(const std::string& path);

// Writes a linear RGB(A) image. PNG values are sRGB-encoded, clamped to [0, 1] and rounded to
// 8 bits; EXR and PFM store the linear values unchanged.
void write_image(const std::string& path, const Image& linear_image);

// Reads an image as stored: 8-bit files give values in [0, 1] still encoded (no decoding is
// applied), float files their float values.
Image read_image(const std::string& path);

}  // namespace obscura

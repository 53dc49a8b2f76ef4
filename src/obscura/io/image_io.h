// Reading and writing image files, through the image codecs plugins (image_codecs.h),
// which are loaded on the first read or write.
//
// The format follows the file's extension:
//   display-referred (developed: exposure, tone map, display encoding, N bits, dither):
//     .png (8-bit, or 16-bit when more than 8 bits are asked for), .jpg/.jpeg (8-bit), .tif/.tiff
//     (8 or 16-bit);
//   scene-referred (linear Rec.709 values as they are):
//     .exr (32-bit float or half, with the Rec.709/D65 chromaticities), .hdr (Radiance RGBE),
//     .pfm (32-bit float);
//   video: .y4m (one frame; see y4m_writer.h for sequences);
//   raw: .dng, a sensor's raw data only (io/dng_file.h): write_image refuses it.
// Files are written to a temporary name beside the target and renamed when complete, so a failed
// or interrupted write never leaves a partial file behind. NaN and ±Inf never reach a file as
// garbage: they are counted (WriteReport) and written as 0 (black); finite values beyond what a
// half-float EXR holds are clamped to its largest value.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "obscura/color/develop.h"
#include "obscura/film/image.h"

namespace obscura {

enum class ImageFormat { kPng, kJpeg, kTiff, kExr, kHdr, kPfm, kY4m, kDng };

// The format for a path's extension (case-insensitive); throws obscura::Error naming the
// extension and the supported ones otherwise.
ImageFormat image_format_for_path(const std::string& path);
// Whether the format stores display-encoded codes (PNG, JPEG, TIFF, Y4M) rather than linear light.
bool is_display_format(ImageFormat f);

// Checks before any work is done that `path` can be written: a supported extension, not a
// directory, a regular file or a new name (never a device, FIFO or socket: obscura::RequestError,
// its message led by `option` when one is given, e.g. "--output"), and a parent directory that
// exists and is writable. Throws obscura::Error.
void check_output_path(const std::string& path, const std::string& option = {});

// Text recorded in the file, where its format has room for it: EXR and PNG keep the description
// and every attribute; TIFF and JPEG the description only; Y4M the attributes, as X tags of its
// stream header; HDR and PFM nothing (format_keeps_metadata tells which).
struct ImageMetadata {
  std::string description;                                      // written as "ImageDescription"
  std::vector<std::pair<std::string, std::string>> attributes;  // e.g. {"obscura:partial", "…"}
  bool empty() const { return description.empty() && attributes.empty(); }
};
// Whether a file of this format can record ImageMetadata (some of it, as above).
bool format_keeps_metadata(ImageFormat f);

struct ImageWriteOptions {
  DisplaySettings display;  // for display formats; default: sRGB, clamp, 8 bits
  bool exr_half = false;    // EXR: 16-bit half instead of 32-bit float
  ImageMetadata metadata;
};

struct WriteReport {
  DevelopStats stats;  // non-finite and out-of-gamut pixel counts
};

// Throws obscura::Error when `output` is the same file as one of `inputs` — compared by identity
// (device and inode), so another spelling, a hard link or a symbolic link is caught too: a
// command never overwrites what it reads.
void check_not_an_input(const std::string& output, const std::vector<std::string>& inputs);

// Writes a linear RGB(A) image (grey images are written as grey where the format allows).
WriteReport write_image(const std::string& path, const Image& linear_image,
                        const ImageWriteOptions& options = {});

// Writes already developed codes to a display format (PNG, JPEG, TIFF).
void write_display_image(const std::string& path, const DisplayImage& image,
                         const ImageMetadata& metadata = {});

// Writes named float channels (any number) to an OpenEXR file exactly as they are, NaN and ±Inf
// included, with `metadata`: data passed between Obscura's own commands (the partial films of
// `render --shard`), not an image for viewing. Atomic like write_image. Throws obscura::Error.
void write_exr_data(const std::string& path, const Image& image, const ImageMetadata& metadata);
// Reads every channel of an OpenEXR file as float, with its string attributes (and description)
// into `metadata`. Throws obscura::Error naming the file.
Image read_exr_data(const std::string& path, ImageMetadata& metadata);

// Reads an image as stored: 8/16-bit files give values in [0, 1] still encoded (no decoding is
// applied), float files their float values. Formats: PNG, JPEG, EXR, HDR, TIFF (native codecs),
// PFM, and BMP, Targa and what else the image reader lets OpenImageIO read.
Image read_image(const std::string& path);

// The view develop() takes, of an Image.
inline LinearPixels pixels_of(const Image& image) {
  return {image.data.data(), image.width, image.height, image.channels};
}

}  // namespace obscura

// The decoded-size limit every image Obscura reads goes through (textures, environment maps,
// glTF images, `obscura image convert`/`diff`): the header is read first and an image whose
// decoded pixels would exceed the limit is refused before any pixel memory is allocated, so a
// small hostile file that declares 20000 × 20000 pixels cannot drive memory into gigabytes.
//
// The limit counts pixels (width × height), 64 Mi (8192 × 8192) by default; images with more
// than four channels count each further group of four channels as another pixel's worth, so the
// decoded float values never exceed 4 × limit (1 GiB at the default). It is raised (or lowered)
// by the environment variable OBSCURA_MAX_IMAGE_PIXELS or, taking precedence, by
// set_max_image_pixels() (the CLI's --max-image-pixels).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace obscura {

inline constexpr uint64_t kDefaultMaxImagePixels = uint64_t(8192) * 8192;
// More channels than any image Obscura reads or writes holds (RGBA, AOV layers); a header
// declaring thousands is hostile, not an image.
inline constexpr int kMaxImageChannels = 64;
// Values in one row (width × channels), fixed: 65536 pixels of 4 channels. OpenImageIO decodes
// scanline files in chunks of up to 256 rows, allocated from the row size, so a 1 000 000 × 1
// image within the pixel limit would still make it allocate gigabytes.
inline constexpr uint64_t kMaxImageRowValues = uint64_t(65536) * 4;

// The limit in force: the value set by set_max_image_pixels(), else OBSCURA_MAX_IMAGE_PIXELS,
// else kDefaultMaxImagePixels. Throws obscura::Error naming the variable when it is not a
// positive whole number.
uint64_t max_image_pixels();

// Sets the limit for this process (std::nullopt: back to the environment variable or default).
// Throws obscura::Error when `pixels` is 0.
void set_max_image_pixels(std::optional<uint64_t> pixels);

// Throws obscura::Error naming `source` when an image of this header may not be decoded: a size
// or channel count of 0 or less, a volume (depth > 1), more than kMaxImageChannels channels, rows
// of more than kMaxImageRowValues values, or more pixels than max_image_pixels(). The message says
// how to raise the limit.
void check_decoded_size(const std::string& source, int64_t width, int64_t height, int64_t depth,
                        int64_t channels);

}  // namespace obscura

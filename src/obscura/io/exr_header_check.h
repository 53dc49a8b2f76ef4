// A structural check of an OpenEXR file's header, run before OpenEXR parses it: OpenEXR allocates
// each attribute's declared size (up to 2 GB for one string attribute) before it reads the bytes,
// so a few hundred hostile bytes could claim gigabytes. Every attribute must fit in the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace obscura {

// Whether `magic` (the file's first 4 bytes) starts an OpenEXR file.
bool is_exr_magic(const uint8_t magic[4]);

// Reads `size` bytes at `offset` into `out`; false when they are not all there.
using ByteReader = std::function<bool(uint64_t offset, size_t size, uint8_t* out)>;

// Walks the header(s) of an OpenEXR file of `total_size` bytes and throws obscura::Error naming
// `source` when an attribute declares a negative size or more bytes than the file holds, a value
// whose layout disagrees with its declared size (fixed-size types, channel lists, previews,
// string vectors), or a name runs past the end of the file.
void check_exr_header(const ByteReader& read, uint64_t total_size, const std::string& source);

}  // namespace obscura

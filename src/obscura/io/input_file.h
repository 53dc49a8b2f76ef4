// The check every whole-file reader makes before reading: a regular file of bounded size.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace obscura {

// Throws obscura::Error naming `path` unless it is a regular file — not a directory, nor a FIFO
// or device such as /dev/zero, which would be read forever — of at most `max_bytes`; returns its
// size. `kind` names such files in the message ("mesh files", "glTF files and buffers").
uint64_t check_input_file(const std::string& path, uint64_t max_bytes, std::string_view kind);

}  // namespace obscura

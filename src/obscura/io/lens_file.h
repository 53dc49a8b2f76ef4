// A lens prescription file (camera/lens_prescription_file.h) read as every other input file is
// (io/input_file.h): a regular file of bounded size, so that a FIFO does not block for ever and
// /dev/zero is not read until memory runs out.
#pragma once

#include <cstdint>
#include <string>

#include "obscura/camera/lens_prescription_file.h"

namespace obscura {

// A real lens has tens of rows of a few dozen bytes; 1 MiB is tens of thousands.
inline constexpr uint64_t kMaxLensFileBytes = uint64_t(1) << 20;

// Checks the file (check_input_file) and parses it. Throws obscura::Error naming the file.
LensPrescription load_checked_lens_prescription(const std::string& path);

}  // namespace obscura

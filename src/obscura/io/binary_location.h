// Where the code of this library lives on disk, so that it finds what ships with it (plugins,
// example scenes) relative to itself rather than to the working directory or the interpreter.
#pragma once

#include <filesystem>

namespace obscura {

// The file this library's code was loaded from: the Python extension module when the library is
// linked into it, else the executable. Symbolic links resolved; empty when it cannot be told.
std::filesystem::path binary_holding_this_library();

}  // namespace obscura

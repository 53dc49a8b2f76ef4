#include "obscura/io/lens_file.h"

#include "obscura/io/input_file.h"

namespace obscura {

LensPrescription load_checked_lens_prescription(const std::string& path) {
  check_input_file(path, kMaxLensFileBytes, "lens prescription files");
  return load_lens_prescription(path);
}

}  // namespace obscura

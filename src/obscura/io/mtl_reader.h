// Wavefront MTL material libraries, parsed into plain records (no files opened here: the OBJ
// loader resolves texture paths and reads the images).
//
// Read: newmtl, Ka, Kd, Ks, Ns, Ke, d, map_Kd, map_Ke (texture options such as "-s 1 1 1" are
// skipped). Everything else (illum, Ni, Tf, map_Bump, …) is ignored, as Assimp ignored it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "obscura/color/rgb.h"

namespace obscura {

struct MtlMaterial {
  std::string name;
  // The values of a material the file names but does not set, as Assimp gave them.
  Rgb ambient{0.f};
  Rgb diffuse{0.6f};
  Rgb specular{0.f};
  Rgb emission{0.f};
  float shininess = 0;       // Ns, clamped to ≥ 0
  float dissolve = 1;        // d: 1 = opaque; read and reported, not rendered
  std::string diffuse_map;   // map_Kd as written (relative to the OBJ file's folder)
  std::string emission_map;  // map_Ke
  size_t line = 0;           // of its newmtl, for messages
};

// Parses MTL text. `name` prefixes messages ("file.mtl:12: …"); throws obscura::Error for a
// statement with missing, malformed, non-finite or negative numbers. What is read but not
// applied (transparency) is appended to `warnings`.
std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& name,
                                   std::vector<std::string>& warnings);

}  // namespace obscura

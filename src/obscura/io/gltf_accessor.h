// The one place glTF accessor data is read: vertex attributes, indices and animation samplers
// all go through GltfAccessorReader, which validates an accessor against the glTF 2.0 rules
// (component and element type, normalized, count, byteOffset, byteStride, the bufferView inside
// its buffer and the accessor inside its bufferView) with overflow-checked arithmetic BEFORE it
// allocates anything, and keeps what a whole file may decode to under a fixed budget, so a
// hostile count (2^62 elements over a 648-byte buffer) is a clear error, never an allocation.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Accessor;
}  // namespace tinygltf

namespace obscura {

// Which component types an accessor may use, by the role it plays (glTF 2.0 §3.7.2.1 with
// KHR_mesh_quantization, §3.11 for animation samplers).
enum class AccessorNumbers {
  kFloat,                // FLOAT only
  kFloatOrNormalized,    // FLOAT, or normalized (UNSIGNED_)BYTE / (UNSIGNED_)SHORT
  kFloatOrSmallInteger,  // FLOAT, or (UNSIGNED_)BYTE / (UNSIGNED_)SHORT, normalized or not
};

class GltfAccessorReader {
 public:
  // What all accessors of one file may decode to together: 1 GiB (268 M floats), far above any
  // scene a renderer on one machine can use, and far below what a hostile count would allocate.
  static constexpr uint64_t kDefaultDecodeBudgetBytes = uint64_t(1) << 30;

  // `file` prefixes every message. `budget_bytes` bounds the sum of all decoded arrays.
  GltfAccessorReader(const tinygltf::Model& model, std::string file,
                     uint64_t budget_bytes = kDefaultDecodeBudgetBytes);

  // Components per element of accessor `index` (1 for SCALAR … 16 for MAT4), after checking
  // the index; `where` is the JSON path of the reference (e.g. "meshes[0].primitives[1].indices").
  int components(int index, const std::string& where) const;
  // Number of elements of accessor `index`.
  uint64_t count(int index, const std::string& where) const;

  // Elements of `components` numbers each (one of `allowed_components`; 16 means a FLOAT MAT4,
  // column-major as stored), flattened; normalized
  // integers map to [0, 1] or [−1, 1] as the spec says, other integers keep their value.
  // Sparse substitutions (§3.6.2.5) are applied, validated like the dense data.
  std::vector<float> floats(int index, std::initializer_list<int> allowed_components,
                            AccessorNumbers numbers, const std::string& where);

  // A SCALAR UNSIGNED_BYTE / UNSIGNED_SHORT / UNSIGNED_INT accessor of vertex indices, every
  // one below `vertex_count`.
  std::vector<uint32_t> indices(int index, uint64_t vertex_count, const std::string& where);

  uint64_t decoded_bytes() const { return decoded_bytes_; }

 private:
  struct Layout;
  const tinygltf::Accessor& accessor(int index, const std::string& where) const;
  Layout layout(int index, const std::string& at) const;
  void charge(uint64_t bytes, const std::string& at);
  // `bytes` from `offset` inside bufferView `view_index`, range-checked; throws naming `at`.
  const uint8_t* view_range(int view_index, uint64_t offset, uint64_t bytes,
                            const std::string& at) const;
  // Applies accessor `index`'s sparse substitutions to its decoded elements.
  void apply_sparse(int index, std::vector<float>& out, const std::string& at) const;

  const tinygltf::Model& model_;
  std::string file_;
  uint64_t budget_bytes_;
  uint64_t decoded_bytes_ = 0;
};

}  // namespace obscura

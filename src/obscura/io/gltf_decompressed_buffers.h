// Where compressed glTF geometry (KHR_draco_mesh_compression, EXT_meshopt_compression) goes once
// decoded: new buffers appended to the model, so that the accessor reader validates and reads
// them like any other data. What one file may decompress to is bounded, because a hostile
// header can claim any count while the compressed bytes stay small.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace obscura {

class GltfDecompressedBuffers {
 public:
  // 1 GiB over all of a file's compressed geometry: far above what a renderer on one machine
  // uses, far below what a forged count would allocate.
  static constexpr uint64_t kDefaultBudgetBytes = uint64_t(1) << 30;

  explicit GltfDecompressedBuffers(tinygltf::Model& model,
                                   uint64_t budget_bytes = kDefaultBudgetBytes)
      : model_(model), budget_bytes_(budget_bytes) {}

  // Counts `bytes` against the budget before they are allocated; throws obscura::Error naming
  // `at` when the file would exceed it.
  void charge(uint64_t bytes, const std::string& at);
  // Appends `data` as a new buffer of the model and returns its index.
  int append(std::vector<unsigned char> data);

 private:
  tinygltf::Model& model_;
  uint64_t budget_bytes_;
  uint64_t used_bytes_ = 0;
};

}  // namespace obscura

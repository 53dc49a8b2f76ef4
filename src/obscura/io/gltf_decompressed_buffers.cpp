#include "obscura/io/gltf_decompressed_buffers.h"

#include <tiny_gltf.h>

#include "obscura/math/error.h"

namespace obscura {

void GltfDecompressedBuffers::charge(uint64_t bytes, const std::string& at) {
  uint64_t total = 0;
  if (__builtin_add_overflow(used_bytes_, bytes, &total) || total > budget_bytes_)
    throw Error(at, "the file's compressed geometry decompresses to more than " +
                        std::to_string(budget_bytes_ >> 20) + " MiB (this part claims " +
                        std::to_string(bytes) + " bytes): too large or hostile");
  used_bytes_ = total;
}

int GltfDecompressedBuffers::append(std::vector<unsigned char> data) {
  tinygltf::Buffer buffer;
  buffer.data = std::move(data);
  model_.buffers.push_back(std::move(buffer));
  return int(model_.buffers.size()) - 1;
}

}  // namespace obscura

#include "obscura/io/gltf_accessor.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

#include "obscura/math/error.h"

namespace obscura {

namespace {

// a × b and a + b, or nothing when the result does not fit in 64 bits.
bool multiply(uint64_t a, uint64_t b, uint64_t* out) {
  return !__builtin_mul_overflow(a, b, out);
}
bool add(uint64_t a, uint64_t b, uint64_t* out) {
  return !__builtin_add_overflow(a, b, out);
}

std::string type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT2:
      return "MAT2";
    case TINYGLTF_TYPE_MAT3:
      return "MAT3";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "type " + std::to_string(type);
  }
}

std::string component_type_name(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    default:
      return "componentType " + std::to_string(component_type);
  }
}

std::string vector_type_name(int components) {
  if (components == 16) return "MAT4";
  return components == 1 ? "SCALAR" : "VEC" + std::to_string(components);
}

template <typename T>
T load(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

}  // namespace

// An accessor's validated place in memory.
struct GltfAccessorReader::Layout {
  const uint8_t* data = nullptr;  // the first element; nullptr: no bufferView, all zeros
  uint64_t count = 0;
  uint64_t stride = 0;
  int type = 0;
  int component_type = 0;
  int components = 0;
  int component_size = 0;
  bool normalized = false;
  bool sparse = false;  // substitutions follow (floats() applies them)
};

namespace {

// One element of `n` components at p, as floats (normalized integers to [0, 1] or [−1, 1]).
void decode_element(const uint8_t* p, int component_type, bool normalized, int n, float* o) {
  for (int c = 0; c < n; ++c) switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        o[c] = load<float>(p + 4 * c);
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        o[c] = normalized ? p[c] / 255.f : float(p[c]);
        break;
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        o[c] = normalized ? std::max(float(int8_t(p[c])) / 127.f, -1.f) : float(int8_t(p[c]));
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        float v = load<uint16_t>(p + 2 * c);
        o[c] = normalized ? v / 65535.f : v;
        break;
      }
      default: {  // SHORT: the only small integer left
        float v = load<int16_t>(p + 2 * c);
        o[c] = normalized ? std::max(v / 32767.f, -1.f) : v;
        break;
      }
    }
}

}  // namespace

GltfAccessorReader::GltfAccessorReader(const tinygltf::Model& model, std::string file,
                                       uint64_t budget_bytes)
    : model_(model), file_(std::move(file)), budget_bytes_(budget_bytes) {}

int GltfAccessorReader::components(int index, const std::string& where) const {
  return layout(index, where).components;
}

uint64_t GltfAccessorReader::count(int index, const std::string& where) const {
  return layout(index, where).count;
}

const tinygltf::Accessor& GltfAccessorReader::accessor(int index, const std::string& where) const {
  if (index < 0 || size_t(index) >= model_.accessors.size())
    throw Error(file_ + ": " + where, "accessor index " + std::to_string(index) +
                                          " is out of range (the file has " +
                                          std::to_string(model_.accessors.size()) + ")");
  return model_.accessors[size_t(index)];
}

GltfAccessorReader::Layout GltfAccessorReader::layout(int index, const std::string& where) const {
  const tinygltf::Accessor& a = accessor(index, where);
  const std::string at = file_ + ": " + where + " (accessor " + std::to_string(index) + ")";
  Layout l;
  l.type = a.type;
  l.component_type = a.componentType;
  l.components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  l.component_size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  l.normalized = a.normalized;
  l.count = a.count;
  if (l.components <= 0) throw Error(at, "invalid element type " + std::to_string(a.type));
  if (l.component_size <= 0)
    throw Error(at, "invalid componentType " + std::to_string(a.componentType));
  if (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                       a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    throw Error(at, "normalized must not be true for " + component_type_name(a.componentType));
  if (a.count == 0) throw Error(at, "count must be at least 1");
  l.sparse = a.sparse.isSparse;

  // Matrix columns start on 4-byte boundaries (glTF 2.0 §3.6.2.4): 1- and 2-byte MAT2/MAT3
  // elements carry padding; every other element is its components, packed.
  uint64_t column_bytes = 0, columns = 1;
  if (a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3 ||
      a.type == TINYGLTF_TYPE_MAT4) {
    columns = a.type == TINYGLTF_TYPE_MAT2 ? 2 : a.type == TINYGLTF_TYPE_MAT3 ? 3 : 4;
    column_bytes = (columns * uint64_t(l.component_size) + 3) / 4 * 4;
  } else {
    column_bytes = uint64_t(l.components) * uint64_t(l.component_size);
  }
  const uint64_t element_size = column_bytes * columns;

  if (a.bufferView < 0) {
    // No data: every element is zero (§3.6.2.3). The count alone is bounded by the budget.
    if (a.byteOffset != 0) throw Error(at, "byteOffset without a bufferView");
    return l;
  }
  if (size_t(a.bufferView) >= model_.bufferViews.size())
    throw Error(at, "bufferView " + std::to_string(a.bufferView) +
                        " is out of range (the file has " +
                        std::to_string(model_.bufferViews.size()) + ")");
  const tinygltf::BufferView& view = model_.bufferViews[size_t(a.bufferView)];
  const std::string view_name = "bufferView " + std::to_string(a.bufferView);
  const std::string view_at = file_ + ": bufferViews[" + std::to_string(a.bufferView) + "]";
  if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
    throw Error(view_at, "buffer index " + std::to_string(view.buffer) +
                             " is out of range (the file has " +
                             std::to_string(model_.buffers.size()) + ")");
  const std::vector<unsigned char>& buffer = model_.buffers[size_t(view.buffer)].data;
  uint64_t view_end = 0;
  if (view.byteLength == 0) throw Error(view_at, "byteLength must be at least 1");
  if (!add(view.byteOffset, view.byteLength, &view_end) || view_end > buffer.size())
    throw Error(view_at, "byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
                             std::to_string(view.byteLength) + " exceeds buffer " +
                             std::to_string(view.buffer) + " (" + std::to_string(buffer.size()) +
                             " bytes)");

  // §3.6.2.4: offsets are multiples of the component size; a stride is at least one element,
  // at most 252 bytes and a multiple of 4 (and so of every component size).
  if (a.byteOffset % uint64_t(l.component_size) != 0 ||
      (view.byteOffset + a.byteOffset) % uint64_t(l.component_size) != 0)
    throw Error(at, "byteOffset " + std::to_string(a.byteOffset) + " (+ " + view_name +
                        " byteOffset " + std::to_string(view.byteOffset) +
                        ") is not a multiple of the component size " +
                        std::to_string(l.component_size));
  l.stride = view.byteStride ? view.byteStride : element_size;
  if (view.byteStride != 0 &&
      (view.byteStride < element_size || view.byteStride > 252 || view.byteStride % 4 != 0))
    throw Error(at, view_name + " byteStride " + std::to_string(view.byteStride) +
                        " must be a multiple of 4 from " + std::to_string(element_size) + " (one " +
                        type_name(a.type) + " of " + component_type_name(a.componentType) +
                        ") to 252");

  // The last element ends at byteOffset + stride × (count − 1) + element size.
  uint64_t span = 0, end = 0;
  if (!multiply(l.stride, a.count - 1, &span) || !add(span, a.byteOffset, &end) ||
      !add(end, element_size, &end) || end > view.byteLength)
    throw Error(at, "count " + std::to_string(a.count) + " × stride " + std::to_string(l.stride) +
                        (a.byteOffset ? " from byteOffset " + std::to_string(a.byteOffset) : "") +
                        " exceeds " + view_name + " (" + std::to_string(view.byteLength) +
                        " bytes)");
  l.data = buffer.data() + view.byteOffset + a.byteOffset;
  return l;
}

void GltfAccessorReader::charge(uint64_t bytes, const std::string& at) {
  uint64_t total = 0;
  if (!add(decoded_bytes_, bytes, &total) || total > budget_bytes_)
    throw Error(at, "the file's accessors decode to more than " +
                        std::to_string(budget_bytes_ >> 20) + " MiB (this one adds " +
                        std::to_string(bytes >> 20) + " MiB): too large or hostile");
  decoded_bytes_ = total;
}

std::vector<float> GltfAccessorReader::floats(int index,
                                              std::initializer_list<int> allowed_components,
                                              AccessorNumbers numbers, const std::string& where) {
  // The element and component types first: they explain more than a range error would.
  Layout l;
  {
    const tinygltf::Accessor& a = accessor(index, where);
    l.type = a.type;
    l.component_type = a.componentType;
    l.components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    l.normalized = a.normalized;
  }
  const std::string at = file_ + ": " + where + " (accessor " + std::to_string(index) + ")";
  bool vector = l.type == TINYGLTF_TYPE_SCALAR || l.type == TINYGLTF_TYPE_VEC2 ||
                l.type == TINYGLTF_TYPE_VEC3 || l.type == TINYGLTF_TYPE_VEC4 ||
                // Float MAT4 (inverse bind matrices): columns need no padding, read as 16 floats.
                (l.type == TINYGLTF_TYPE_MAT4 && l.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT);
  if (!vector || std::find(allowed_components.begin(), allowed_components.end(), l.components) ==
                     allowed_components.end()) {
    std::string expected;
    for (int c : allowed_components)
      expected += (expected.empty() ? "" : " or ") + vector_type_name(c);
    throw Error(at, "expected " + expected + ", got " + type_name(l.type));
  }
  bool is_float = l.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
  bool small_integer = l.component_type == TINYGLTF_COMPONENT_TYPE_BYTE ||
                       l.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                       l.component_type == TINYGLTF_COMPONENT_TYPE_SHORT ||
                       l.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  bool accepted =
      is_float ||
      (numbers == AccessorNumbers::kFloatOrNormalized && small_integer && l.normalized) ||
      (numbers == AccessorNumbers::kFloatOrSmallInteger && small_integer);
  if (!accepted)
    throw Error(
        at, std::string(l.normalized ? "normalized " : "") + component_type_name(l.component_type) +
                " is not allowed here (expected FLOAT" +
                (numbers == AccessorNumbers::kFloatOrNormalized     ? ", or normalized BYTE/SHORT)"
                 : numbers == AccessorNumbers::kFloatOrSmallInteger ? ", BYTE or SHORT)"
                                                                    : ")"));
  l = layout(index, where);
  uint64_t values = 0, bytes = 0;
  if (!multiply(l.count, uint64_t(l.components), &values) ||
      !multiply(values, sizeof(float), &bytes))
    throw Error(at, "count " + std::to_string(l.count) + " is too large");
  charge(bytes, at);
  std::vector<float> out(values, 0.f);
  const int n = l.components;
  if (l.data)
    for (uint64_t i = 0; i < l.count; ++i)
      decode_element(l.data + i * l.stride, l.component_type, l.normalized, n, out.data() + i * n);
  if (l.sparse) apply_sparse(index, out, at);
  return out;
}

const uint8_t* GltfAccessorReader::view_range(int view_index, uint64_t offset, uint64_t bytes,
                                              const std::string& at) const {
  if (view_index < 0 || size_t(view_index) >= model_.bufferViews.size())
    throw Error(at, "bufferView " + std::to_string(view_index) + " is out of range (the file has " +
                        std::to_string(model_.bufferViews.size()) + ")");
  const tinygltf::BufferView& view = model_.bufferViews[size_t(view_index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
    throw Error(at, "bufferView " + std::to_string(view_index) + " names buffer " +
                        std::to_string(view.buffer) + ", which is out of range");
  const std::vector<unsigned char>& buffer = model_.buffers[size_t(view.buffer)].data;
  uint64_t view_end = 0, end = 0;
  if (!add(view.byteOffset, view.byteLength, &view_end) || view_end > buffer.size() ||
      !add(offset, bytes, &end) || end > view.byteLength)
    throw Error(at, std::to_string(bytes) + " bytes from byteOffset " + std::to_string(offset) +
                        " exceed bufferView " + std::to_string(view_index) + " (" +
                        std::to_string(view.byteLength) + " bytes)");
  return buffer.data() + view.byteOffset + offset;
}

void GltfAccessorReader::apply_sparse(int index, std::vector<float>& out,
                                      const std::string& at) const {
  // §3.6.2.5: `count` substitutions; strictly increasing indices below the accessor's count;
  // values tightly packed, of the accessor's own element and component type.
  const tinygltf::Accessor& a = model_.accessors[size_t(index)];
  const std::string where = at + ".sparse";
  const uint64_t n = uint64_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
  if (a.sparse.count < 1 || uint64_t(a.sparse.count) > a.count)
    throw Error(where, "count " + std::to_string(a.sparse.count) +
                           " must be from 1 to the "
                           "accessor's count " +
                           std::to_string(a.count));
  const int index_type = a.sparse.indices.componentType;
  if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw Error(where + ".indices",
                "componentType must be UNSIGNED_BYTE, UNSIGNED_SHORT or "
                "UNSIGNED_INT, got " +
                    component_type_name(index_type));
  const uint64_t count = uint64_t(a.sparse.count);
  const uint64_t index_size = uint64_t(tinygltf::GetComponentSizeInBytes(uint32_t(index_type)));
  const uint64_t value_size =
      n * uint64_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
    throw Error(where, "negative byteOffset");
  const uint8_t* indices =
      view_range(a.sparse.indices.bufferView, uint64_t(a.sparse.indices.byteOffset),
                 count * index_size, where + ".indices");
  const uint8_t* values =
      view_range(a.sparse.values.bufferView, uint64_t(a.sparse.values.byteOffset),
                 count * value_size, where + ".values");
  uint64_t previous = 0;
  for (uint64_t i = 0; i < count; ++i) {
    const uint8_t* p = indices + i * index_size;
    uint64_t target = index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? *p
                      : index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? load<uint16_t>(p)
                                                                             : load<uint32_t>(p);
    if (target >= a.count || (i > 0 && target <= previous))
      throw Error(where + ".indices",
                  "index " + std::to_string(i) + " = " + std::to_string(target) +
                      " is not increasing or not below the count " + std::to_string(a.count));
    previous = target;
    decode_element(values + i * value_size, a.componentType, a.normalized, int(n),
                   out.data() + target * n);
  }
}

std::vector<uint32_t> GltfAccessorReader::indices(int index, uint64_t vertex_count,
                                                  const std::string& where) {
  const tinygltf::Accessor& a = accessor(index, where);
  const std::string at = file_ + ": " + where + " (accessor " + std::to_string(index) + ")";
  if (a.type != TINYGLTF_TYPE_SCALAR)
    throw Error(at, "indices must be SCALAR, got " + type_name(a.type));
  if ((a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
       a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
       a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) ||
      a.normalized)
    throw Error(at, "indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got " +
                        std::string(a.normalized ? "normalized " : "") +
                        component_type_name(a.componentType));
  const Layout l = layout(index, where);
  if (l.sparse) throw Error(at, "sparse index accessors are not supported");
  uint64_t bytes = 0;
  if (!multiply(l.count, sizeof(uint32_t), &bytes))
    throw Error(at, "count " + std::to_string(l.count) + " is too large");
  charge(bytes, at);
  std::vector<uint32_t> out(l.count, 0);
  if (!l.data) return out;  // all zeros: valid when there is at least one vertex
  for (uint64_t i = 0; i < l.count; ++i) {
    const uint8_t* p = l.data + i * l.stride;
    out[i] = l.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? *p
             : l.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? load<uint16_t>(p)
                                                                          : load<uint32_t>(p);
    if (out[i] >= vertex_count)
      throw Error(file_ + ": " + where, "index " + std::to_string(i) + " = " +
                                            std::to_string(out[i]) + " is past the vertex count " +
                                            std::to_string(vertex_count));
  }
  return out;
}

}  // namespace obscura

#include "obscura/io/gltf_draco.h"

#include <draco/compression/decode.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <new>

#include "obscura/io/gltf_decompressed_buffers.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// One decoded element type: the accessor's components, converted by Draco to the accessor's
// component type (normalized integers scaled, as the accessor's normalized flag says).
template <typename T>
bool convert(const draco::PointAttribute& attribute, uint32_t points, int components,
             unsigned char* out) {
  std::vector<T> element(static_cast<size_t>(components));
  for (uint32_t i = 0; i < points; ++i) {
    draco::AttributeValueIndex value = attribute.mapped_index(draco::PointIndex(i));
    if (value.value() >= attribute.size() ||
        !attribute.ConvertValue<T>(value, int8_t(components), element.data()))
      return false;
    std::memcpy(out + size_t(i) * sizeof(T) * size_t(components), element.data(),
                sizeof(T) * size_t(components));
  }
  return true;
}

// Float values into a normalized integer type: clamped to [0, 1] (unsigned) or [−1, 1] and
// scaled by the type's maximum, rounded (glTF 2.0 §3.11's inverse).
template <typename T>
bool normalize(const draco::PointAttribute& attribute, uint32_t points, int components,
               unsigned char* out) {
  std::vector<float> element(static_cast<size_t>(components));
  constexpr float kMax = float(std::numeric_limits<T>::max());
  constexpr float kMin = std::numeric_limits<T>::is_signed ? -1.f : 0.f;
  for (uint32_t i = 0; i < points; ++i) {
    draco::AttributeValueIndex value = attribute.mapped_index(draco::PointIndex(i));
    if (value.value() >= attribute.size() ||
        !attribute.ConvertValue<float>(value, int8_t(components), element.data()))
      return false;
    for (int c = 0; c < components; ++c) {
      float v = element[size_t(c)];
      if (!std::isfinite(v)) return false;
      T q = T(std::lround(std::clamp(v, kMin, 1.f) * kMax));
      std::memcpy(out + (size_t(i) * size_t(components) + size_t(c)) * sizeof(T), &q, sizeof(T));
    }
  }
  return true;
}

bool convert_attribute(const draco::PointAttribute& attribute, uint32_t points, int components,
                       int component_type, bool normalized, unsigned char* out) {
  // Draco dequantizes to floats unless the encoder stored integers; a normalized accessor over
  // float values wants them quantized back. Integers are copied as they are (range-checked).
  bool from_float =
      attribute.data_type() == draco::DT_FLOAT32 || attribute.data_type() == draco::DT_FLOAT64;
  if (from_float && normalized) switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return normalize<int8_t>(attribute, points, components, out);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalize<uint8_t>(attribute, points, components, out);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return normalize<int16_t>(attribute, points, components, out);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return normalize<uint16_t>(attribute, points, components, out);
      default:
        return false;
    }
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return convert<float>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return convert<int8_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return convert<uint8_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return convert<int16_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return convert<uint16_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return convert<uint32_t>(attribute, points, components, out);
    default:
      return false;
  }
}

class DracoDecoder {
 public:
  DracoDecoder(tinygltf::Model& model, std::string file, GltfDecompressedBuffers& buffers)
      : model_(model), file_(std::move(file)), buffers_(buffers) {}

  void decode_primitive(tinygltf::Primitive& primitive, const std::string& where);

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw Error(file_ + ": " + where, message);
  }
  const draco::Mesh& mesh(int view_index, const std::string& where);
  tinygltf::Accessor& accessor(int index, const std::string& where);
  // Appends `bytes` as a new buffer with one view and points accessor `index` at it.
  void attach(int index, std::vector<unsigned char> bytes);
  // True when accessor `index` already holds this data; fails when it holds other data.
  bool already_decoded(int index, int view, int attribute_id, const std::string& where);
  std::vector<unsigned char> indices(const draco::Mesh& mesh, const tinygltf::Accessor& a,
                                     const std::string& where);
  std::vector<unsigned char> attribute(const draco::Mesh& mesh, int id, const tinygltf::Accessor& a,
                                       const std::string& where);

  tinygltf::Model& model_;
  std::string file_;
  GltfDecompressedBuffers& buffers_;
  std::map<int, std::unique_ptr<draco::Mesh>> meshes_;  // by bufferView
  // What each accessor was filled with: (bufferView, attribute id; −1 for the indices).
  std::map<int, std::pair<int, int>> sources_;
};

const draco::Mesh& DracoDecoder::mesh(int view_index, const std::string& where) {
  auto found = meshes_.find(view_index);
  if (found != meshes_.end()) return *found->second;
  if (view_index < 0 || size_t(view_index) >= model_.bufferViews.size())
    fail(where + ".bufferView", "bufferView " + std::to_string(view_index) +
                                    " is out of range (the file has " +
                                    std::to_string(model_.bufferViews.size()) + ")");
  const tinygltf::BufferView& view = model_.bufferViews[size_t(view_index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
    fail("bufferViews[" + std::to_string(view_index) + "]",
         "buffer index " + std::to_string(view.buffer) + " is out of range");
  const std::vector<unsigned char>& data = model_.buffers[size_t(view.buffer)].data;
  uint64_t end = 0;
  if (__builtin_add_overflow(uint64_t(view.byteOffset), uint64_t(view.byteLength), &end) ||
      end > data.size())
    fail("bufferViews[" + std::to_string(view_index) + "]",
         "byteOffset + byteLength exceeds buffer " + std::to_string(view.buffer));
  draco::DecoderBuffer stream;
  stream.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
  draco::Decoder decoder;
  std::unique_ptr<draco::Mesh> decoded;
  try {
    auto result = decoder.DecodeMeshFromBuffer(&stream);
    if (!result.ok())
      fail(where + ".bufferView", "the Draco stream in bufferView " + std::to_string(view_index) +
                                      " does not decode to a mesh (" +
                                      result.status().error_msg_string() + ")");
    decoded = std::move(result).value();
  } catch (const std::bad_alloc&) {
    fail(where + ".bufferView", "the Draco stream in bufferView " + std::to_string(view_index) +
                                    " claims more memory than can be had: corrupt or hostile");
  } catch (const std::length_error&) {
    fail(where + ".bufferView", "the Draco stream in bufferView " + std::to_string(view_index) +
                                    " claims more memory than can be had: corrupt or hostile");
  }
  if (!decoded) fail(where + ".bufferView", "the Draco stream holds no mesh");
  return *(meshes_[view_index] = std::move(decoded));
}

tinygltf::Accessor& DracoDecoder::accessor(int index, const std::string& where) {
  if (index < 0 || size_t(index) >= model_.accessors.size())
    fail(where, "accessor index " + std::to_string(index) + " is out of range (the file has " +
                    std::to_string(model_.accessors.size()) + ")");
  return model_.accessors[size_t(index)];
}

bool DracoDecoder::already_decoded(int index, int view, int attribute_id,
                                   const std::string& where) {
  auto found = sources_.find(index);
  if (found == sources_.end()) {
    sources_[index] = {view, attribute_id};
    return false;
  }
  if (found->second != std::make_pair(view, attribute_id))
    fail(where, "accessor " + std::to_string(index) +
                    " is filled by two different Draco attributes (or by indices and an "
                    "attribute)");
  return true;
}

void DracoDecoder::attach(int index, std::vector<unsigned char> bytes) {
  tinygltf::BufferView view;
  view.byteLength = bytes.size();
  view.buffer = buffers_.append(std::move(bytes));
  model_.bufferViews.push_back(view);
  tinygltf::Accessor& a = model_.accessors[size_t(index)];
  a.bufferView = int(model_.bufferViews.size()) - 1;
  a.byteOffset = 0;
  a.sparse.isSparse = false;  // the decoded data is the whole accessor
}

std::vector<unsigned char> DracoDecoder::indices(const draco::Mesh& mesh,
                                                 const tinygltf::Accessor& a,
                                                 const std::string& where) {
  const uint64_t faces = mesh.num_faces(), points = mesh.num_points();
  if (a.type != TINYGLTF_TYPE_SCALAR) fail(where, "indices must be SCALAR");
  if (a.count != faces * 3)
    fail(where, "the accessor's count " + std::to_string(a.count) + " differs from the " +
                    std::to_string(faces * 3) + " indices of the Draco mesh's " +
                    std::to_string(faces) + " triangles");
  uint64_t size = 0, limit = 0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      size = 1, limit = 0xff;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      size = 2, limit = 0xffff;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      size = 4, limit = 0xffffffff;
      break;
    default:
      fail(where, "indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
  buffers_.charge(a.count * size, file_ + ": " + where);
  std::vector<unsigned char> out(a.count * size);
  for (uint32_t f = 0; f < faces; ++f) {
    const draco::Mesh::Face& face = mesh.face(draco::FaceIndex(f));
    for (int k = 0; k < 3; ++k) {
      uint64_t v = face[size_t(k)].value();
      if (v >= points || v > limit)
        fail(where, "Draco triangle " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                        ", past the " + std::to_string(points) + " points or the component type");
      uint32_t v32 = uint32_t(v);
      uint8_t* p = out.data() + (uint64_t(f) * 3 + uint64_t(k)) * size;
      if (size == 1) *p = uint8_t(v32);
      if (size == 2) {
        uint16_t v16 = uint16_t(v32);
        std::memcpy(p, &v16, 2);
      }
      if (size == 4) std::memcpy(p, &v32, 4);
    }
  }
  return out;
}

std::vector<unsigned char> DracoDecoder::attribute(const draco::Mesh& mesh, int id,
                                                   const tinygltf::Accessor& a,
                                                   const std::string& where) {
  const draco::PointAttribute* attribute =
      id >= 0 ? mesh.GetAttributeByUniqueId(uint32_t(id)) : nullptr;
  if (!attribute) fail(where, "the Draco mesh has no attribute with id " + std::to_string(id));
  const uint64_t points = mesh.num_points();
  if (a.count != points)
    fail(where, "the accessor's count " + std::to_string(a.count) + " differs from the Draco " +
                    "mesh's " + std::to_string(points) + " points");
  int components = a.type == TINYGLTF_TYPE_SCALAR ? 1
                   : a.type == TINYGLTF_TYPE_VEC2 ? 2
                   : a.type == TINYGLTF_TYPE_VEC3 ? 3
                   : a.type == TINYGLTF_TYPE_VEC4 ? 4
                                                  : 0;
  if (components == 0) fail(where, "a Draco attribute must be SCALAR or VEC2–VEC4");
  if (attribute->num_components() != components)
    fail(where, "the Draco attribute has " + std::to_string(attribute->num_components()) +
                    " components per element, the accessor " + std::to_string(components));
  int component_size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (component_size <= 0) fail(where, "invalid componentType " + std::to_string(a.componentType));
  uint64_t bytes = points * uint64_t(components) * uint64_t(component_size);
  buffers_.charge(bytes, file_ + ": " + where);
  std::vector<unsigned char> out(bytes);
  if (!convert_attribute(*attribute, uint32_t(points), components, a.componentType, a.normalized,
                         out.data()))
    fail(where, "the Draco attribute's values do not fit the accessor's component type");
  return out;
}

void DracoDecoder::decode_primitive(tinygltf::Primitive& primitive, const std::string& where) {
  const std::string at = where + ".extensions." + kExtension;
  const tinygltf::Value& ext = primitive.extensions.at(kExtension);
  if (!ext.IsObject() || !ext.Has("bufferView") || !ext.Get("bufferView").IsInt() ||
      !ext.Has("attributes") || !ext.Get("attributes").IsObject())
    fail(at, "expected an object with an integer bufferView and an attributes object");
  const int view = ext.Get("bufferView").GetNumberAsInt();
  const draco::Mesh& decoded = mesh(view, at);
  if (primitive.indices >= 0) {
    const std::string index_at = where + ".indices";
    tinygltf::Accessor& a = accessor(primitive.indices, index_at);
    if (!already_decoded(primitive.indices, view, -1, index_at))
      attach(primitive.indices, indices(decoded, a, index_at));
  }
  const tinygltf::Value& ids = ext.Get("attributes");
  for (const std::string& semantic : ids.Keys()) {
    const std::string attribute_at = at + ".attributes." + semantic;
    const tinygltf::Value& id = ids.Get(semantic);
    if (!id.IsInt() || id.GetNumberAsInt() < 0)
      fail(attribute_at, "expected a non-negative integer (a Draco attribute id)");
    auto target = primitive.attributes.find(semantic);
    if (target == primitive.attributes.end())
      fail(attribute_at, "the primitive has no attribute " + semantic + " to decode it into");
    const std::string accessor_at = where + ".attributes." + semantic;
    tinygltf::Accessor& a = accessor(target->second, accessor_at);
    if (!already_decoded(target->second, view, id.GetNumberAsInt(), accessor_at))
      attach(target->second, attribute(decoded, id.GetNumberAsInt(), a, accessor_at));
  }
}

}  // namespace

void decode_draco_primitives(tinygltf::Model& model, const std::string& file,
                             GltfDecompressedBuffers& buffers) {
  DracoDecoder decoder(model, file, buffers);
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
      // Draco point clouds (mode POINTS) are not decoded: the loader skips points anyway.
      bool triangles = primitive.mode == TINYGLTF_MODE_TRIANGLES ||
                       primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
                       primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN;
      if (triangles && primitive.extensions.count(kExtension))
        decoder.decode_primitive(
            primitive, "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]");
    }
}

}  // namespace obscura

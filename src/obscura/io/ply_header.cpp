#include "obscura/io/ply_header.h"

#include <charconv>
#include <limits>

#include "obscura/io/mesh_file.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

bool parse_type(std::string_view text, PlyType& out) {
  static const std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::kInt8},      {"int8", PlyType::kInt8},       {"uchar", PlyType::kUint8},
      {"uint8", PlyType::kUint8},    {"short", PlyType::kInt16},     {"int16", PlyType::kInt16},
      {"ushort", PlyType::kUint16},  {"uint16", PlyType::kUint16},   {"int", PlyType::kInt32},
      {"int32", PlyType::kInt32},    {"uint", PlyType::kUint32},     {"uint32", PlyType::kUint32},
      {"float", PlyType::kFloat32},  {"float32", PlyType::kFloat32}, {"double", PlyType::kFloat64},
      {"float64", PlyType::kFloat64}};
  for (auto [type_name, type] : kNames)
    if (text == type_name) {
      out = type;
      return true;
    }
  return false;
}

bool is_integer(PlyType type) {
  return type != PlyType::kFloat32 && type != PlyType::kFloat64;
}

// The fewest bytes one entry of `element` takes after the header (lists empty).
uint64_t minimum_entry_bytes(const PlyElement& element, PlyFormat format) {
  uint64_t bytes = 0;
  for (const PlyProperty& p : element.properties) {
    if (format == PlyFormat::kAscii)
      bytes += 2;  // a digit and a separator (the last value of the file may lack it)
    else
      bytes += ply_type_size(p.is_list ? p.count_type : p.type);
  }
  return bytes;
}

}  // namespace

size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 1;
}

double ply_type_max(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
      return 127;
    case PlyType::kUint8:
      return 255;
    case PlyType::kInt16:
      return 32767;
    case PlyType::kUint16:
      return 65535;
    case PlyType::kInt32:
      return 2147483647.0;
    case PlyType::kUint32:
      return 4294967295.0;
    default:
      return 1;
  }
}

int PlyElement::find(const std::string& property) const {
  for (size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return int(i);
  return -1;
}

PlyHeader parse_ply_header(std::span<const char> bytes, const std::string& name) {
  LineReader lines{std::string_view(bytes.data(), bytes.size())};
  auto fail = [&](const std::string& message) -> void {
    throw Error(name + ":" + std::to_string(lines.line_number), message);
  };
  PlyHeader header;
  std::string_view line;
  if (!lines.next(line) || line != "ply") {
    lines.line_number = 1;
    fail("not a PLY file: it does not start with the line 'ply'");
  }
  bool has_format = false, ended = false;
  while (!ended && lines.next(line)) {
    TextCursor c{line.data(), line.data() + line.size()};
    std::string_view keyword = c.token();
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      std::string_view format = c.token();
      if (format == "ascii")
        header.format = PlyFormat::kAscii;
      else if (format == "binary_little_endian")
        header.format = PlyFormat::kBinaryLittleEndian;
      else if (format == "binary_big_endian")
        header.format = PlyFormat::kBinaryBigEndian;
      else
        fail("unknown format '" + std::string(format.substr(0, 40)) +
             "'; expected ascii, binary_little_endian or binary_big_endian");
      has_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(c.token());
      std::string_view count = c.token();
      auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), element.count);
      if (element.name.empty() || ec != std::errc() || end != count.data() + count.size())
        fail("expected 'element NAME COUNT' with a non-negative integer COUNT");
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail("'property' before any 'element'");
      PlyProperty p;
      std::string_view type = c.token();
      if (type == "list") {
        p.is_list = true;
        if (!parse_type(c.token(), p.count_type) || !is_integer(p.count_type))
          fail("expected 'property list COUNT_TYPE ITEM_TYPE NAME' with an integer COUNT_TYPE");
        type = c.token();
      }
      if (!parse_type(type, p.type))
        fail("unknown property type '" + std::string(type.substr(0, 40)) + "'");
      p.name = std::string(c.token());
      if (p.name.empty()) fail("property without a name");
      header.elements.back().properties.push_back(std::move(p));
    } else if (keyword == "end_header") {
      ended = true;
    } else {
      fail("unknown header line '" + std::string(keyword.substr(0, 40)) + "'");
    }
  }
  if (!ended) fail("the header has no 'end_header' line (truncated, or not a PLY file)");
  if (!has_format) fail("the header has no 'format' line");
  header.data_offset = std::min(lines.offset, bytes.size());
  header.lines = lines.line_number;

  // Every declared entry needs bytes after the header: refuse lying counts before allocating.
  uint64_t available = bytes.size() - header.data_offset;
  uint64_t budget = available + (header.format == PlyFormat::kAscii ? 1 : 0);
  for (const PlyElement& e : header.elements) {
    uint64_t entry = minimum_entry_bytes(e, header.format);
    if (e.count > 0 && entry == 0)
      throw Error(name, "element '" + e.name + "' has entries but no properties");
    if (entry > 0 && e.count > budget / entry)
      throw Error(name, "element '" + e.name + "' declares " + std::to_string(e.count) +
                            " entries, which need at least " +
                            (e.count > std::numeric_limits<uint64_t>::max() / entry
                                 ? std::string("2^64")
                                 : std::to_string(e.count * entry)) +
                            " bytes, but " + std::to_string(available) +
                            " follow the header (truncated, or a wrong count)");
    budget -= e.count * entry;
  }
  return header;
}

}  // namespace obscura

#include "obscura/io/y4m_writer.h"

#include <cctype>
#include <vector>

#include "obscura/color/quantize.h"
#include "obscura/math/error.h"

namespace obscura {

Y4mWriter::Y4mWriter(const std::string& path, int width, int height, const Y4mSettings& settings)
    : path_(path), width_(width), height_(height), settings_(settings) {
  if (width <= 0 || height <= 0) throw Error(path, "Y4M frames must have a positive size");
  bool subsampled = settings.subsampling != ChromaSubsampling::k444;
  if (subsampled &&
      (width % 2 != 0 || (settings.subsampling == ChromaSubsampling::k420 && height % 2 != 0)))
    throw Error(path, "Y4M with " + chroma_subsampling_name(settings.subsampling) +
                          " chroma needs even frame sizes; got " + std::to_string(width) + "x" +
                          std::to_string(height));
  if (settings.fps_numerator <= 0 || settings.fps_denominator <= 0)
    throw Error(path, "Y4M frame rate must be positive");
  file_ = std::make_unique<AtomicFile>(path);
  const char* chroma = settings.subsampling == ChromaSubsampling::k444   ? "C444"
                       : settings.subsampling == ChromaSubsampling::k422 ? "C422"
                                                                         : "C420jpeg";
  file_->write("YUV4MPEG2 W" + std::to_string(width) + " H" + std::to_string(height) + " F" +
               std::to_string(settings.fps_numerator) + ":" +
               std::to_string(settings.fps_denominator) + " Ip A1:1 " + chroma +
               " XCOLORRANGE=" + (settings.range == YcbcrRange::kLimited ? "LIMITED" : "FULL"));
  for (const std::string& tag : settings.header_tags) {
    if (tag.empty() || tag.find_first_of(" \n") != std::string::npos)
      throw Error(path, "Y4M header tag '" + tag + "' is empty or holds a space or line break");
    file_->write(" X" + tag);
  }
  file_->write("\n");
}

std::string y4m_tag(const std::string& name, const std::string& value) {
  std::string tag;
  for (char c : name) tag += c == ':' || c == ' ' ? '_' : char(std::toupper((unsigned char)c));
  tag += '=';
  for (char c : value) tag += c == ' ' || c == '\n' ? '_' : c;
  return tag;
}

Y4mWriter::~Y4mWriter() = default;

void Y4mWriter::write_frame(const DisplayImage& frame) {
  if (!file_) throw Error(path_, "the Y4M writer is closed");
  if (frame.width != width_ || frame.height != height_)
    throw Error(path_, "frame size " + std::to_string(frame.width) + "x" +
                           std::to_string(frame.height) + " differs from the stream's " +
                           std::to_string(width_) + "x" + std::to_string(height_));
  if (frame.bits > 8) throw Error(path_, "Y4M frames are 8-bit; develop with bits ≤ 8");
  std::vector<uint16_t> codes = frame.codes;
  if (frame.bits != 8)
    for (uint16_t& c : codes) c = uint16_t(requantize(c, frame.bits, 8));
  YcbcrPlanes planes = to_ycbcr_planes(codes.data(), width_, height_, frame.channels,
                                       settings_.matrix, settings_.range, settings_.subsampling);
  file_->write(std::string("FRAME\n"));
  for (const std::vector<uint8_t>* plane : {&planes.y, &planes.cb, &planes.cr})
    file_->write(*plane);
  ++frames_;
}

void Y4mWriter::close() {
  if (!file_) return;
  std::unique_ptr<AtomicFile> file = std::move(file_);
  file->commit();
}

}  // namespace obscura

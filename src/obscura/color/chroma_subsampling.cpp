#include "obscura/color/chroma_subsampling.h"

#include "obscura/color/quantize.h"
#include "obscura/math/error.h"

namespace obscura {

std::string chroma_subsampling_name(ChromaSubsampling c) {
  switch (c) {
    case ChromaSubsampling::k444:
      return "444";
    case ChromaSubsampling::k422:
      return "422";
    case ChromaSubsampling::k420:
      return "420";
  }
  return "?";
}

ChromaSubsampling parse_chroma_subsampling(const std::string& name) {
  for (ChromaSubsampling c :
       {ChromaSubsampling::k444, ChromaSubsampling::k422, ChromaSubsampling::k420})
    if (chroma_subsampling_name(c) == name) return c;
  throw Error("chroma subsampling", "unknown '" + name + "'; expected 444, 422 or 420");
}

YcbcrPlanes to_ycbcr_planes(const uint16_t* rgb8, int width, int height, int channels,
                            YcbcrMatrix matrix, YcbcrRange range, ChromaSubsampling subsampling) {
  if (width <= 0 || height <= 0 || channels < 3)
    throw Error("YCbCr planes", "expected a non-empty RGB image");
  int sx = subsampling == ChromaSubsampling::k444 ? 1 : 2;
  int sy = subsampling == ChromaSubsampling::k420 ? 2 : 1;
  YcbcrPlanes p;
  p.width = width, p.height = height;
  p.chroma_width = (width + sx - 1) / sx, p.chroma_height = (height + sy - 1) / sy;
  p.y.resize(size_t(width) * height);
  p.cb.resize(size_t(p.chroma_width) * p.chroma_height);
  p.cr.resize(p.cb.size());
  std::vector<double> cb(p.cb.size(), 0), cr(p.cb.size(), 0), weight(p.cb.size(), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint16_t* px = rgb8 + (size_t(y) * width + x) * channels;
      Vec3d ycc = ycbcr_from_rgb({px[0] / 255.0, px[1] / 255.0, px[2] / 255.0}, matrix);
      p.y[size_t(y) * width + x] = uint8_t(ycbcr_codes(ycc, range).y);
      size_t c = size_t(y / sy) * p.chroma_width + x / sx;
      cb[c] += ycc[1], cr[c] += ycc[2], weight[c] += 1;
    }
  for (size_t c = 0; c < cb.size(); ++c) {
    YcbcrCodes q = ycbcr_codes({0, cb[c] / weight[c], cr[c] / weight[c]}, range);
    p.cb[c] = uint8_t(q.cb), p.cr[c] = uint8_t(q.cr);
  }
  return p;
}

std::vector<uint16_t> rgb_from_ycbcr_planes(const YcbcrPlanes& p, YcbcrMatrix matrix,
                                            YcbcrRange range) {
  int sx = p.width > p.chroma_width ? 2 : 1, sy = p.height > p.chroma_height ? 2 : 1;
  std::vector<uint16_t> rgb(size_t(p.width) * p.height * 3);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      size_t c = size_t(y / sy) * p.chroma_width + x / sx;
      Vec3d ycc = ycbcr_from_codes({p.y[size_t(y) * p.width + x], p.cb[c], p.cr[c]}, range);
      Vec3d v = rgb_from_ycbcr(ycc, matrix);
      for (int k = 0; k < 3; ++k)
        rgb[(size_t(y) * p.width + x) * 3 + k] = uint16_t(quantize(v[k], 8));
    }
  return rgb;
}

}  // namespace obscura

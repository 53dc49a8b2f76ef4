#include "obscura/color/convert_pixels.h"

#include <vector>

namespace obscura {

namespace {

template <typename T>
void convert_rgb_to_rgb(const ColorSpaceInfo& from, const ColorSpaceInfo& to, const T* in, T* out,
                        size_t n) {
  for (size_t p = 0; p < n; ++p) {
    Vec3d linear;
    for (int i = 0; i < 3; ++i)
      linear[i] = decode(from.transfer, double(in[3 * p + size_t(i)])) / from.linear_scale;
    const Vec3d target = to.rgb_from_xyz_d65 * (from.xyz_d65_from_rgb * linear);
    for (int i = 0; i < 3; ++i)
      out[3 * p + size_t(i)] = T(encode(to.transfer, target[i] * to.linear_scale));
  }
}

}  // namespace

template <typename T>
void convert_pixels(const ColorSpaceInfo& from, const ColorSpaceInfo& to, const T* in, T* out,
                    size_t n) {
  if (from.model == ColorModel::kRgb && to.model == ColorModel::kRgb) {
    convert_rgb_to_rgb(from, to, in, out, n);
    return;
  }
  const size_t fc = size_t(from.components), tc = size_t(to.components);
  std::vector<double> values(fc);
  for (size_t p = 0; p < n; ++p) {
    for (size_t k = 0; k < fc; ++k) values[k] = double(in[p * fc + k]);
    const std::vector<double> result = from_xyz_d65(to, xyz_d65_from(from, values));
    for (size_t k = 0; k < tc; ++k) out[p * tc + k] = T(result[k]);
  }
}

template void convert_pixels(const ColorSpaceInfo&, const ColorSpaceInfo&, const float*, float*,
                             size_t);
template void convert_pixels(const ColorSpaceInfo&, const ColorSpaceInfo&, const double*, double*,
                             size_t);

}  // namespace obscura

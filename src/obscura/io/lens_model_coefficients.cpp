#include "obscura/io/lens_model_coefficients.h"

#include <algorithm>

#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

std::string count_text(size_t n) {
  std::string text = number_text(double(n));
  text.append(n == 1 ? " coefficient" : " coefficients");
  return text;
}

}  // namespace

LensModel lens_model_from_coefficients(const std::string& name, const std::vector<double>& c) {
  size_t n = c.size();
  if (name == "opencv") {
    if (n != 4 && n != 5 && n != 8 && n != 12 && n != 14)
      throw Error(
          "opencv expects 4, 5, 8, 12 or 14 coefficients (k1,k2,p1,p2[,k3[,k4,k5,k6[,s1,"
          "s2,s3,s4[,tx,ty]]]]); got " +
          count_text(n));
    std::vector<double> a = c;
    a.resize(14, 0.0);
    return PinholeDistortion{.k1 = a[0],
                             .k2 = a[1],
                             .p1 = a[2],
                             .p2 = a[3],
                             .k3 = a[4],
                             .k4 = a[5],
                             .k5 = a[6],
                             .k6 = a[7],
                             .s1 = a[8],
                             .s2 = a[9],
                             .s3 = a[10],
                             .s4 = a[11],
                             .tau_x = a[12],
                             .tau_y = a[13]};
  }
  if (name == "kannala-brandt") {
    if (n != 4)
      throw Error("kannala-brandt expects 4 coefficients (k1,k2,k3,k4); got " + count_text(n));
    return KannalaBrandt{c[0], c[1], c[2], c[3]};
  }
  if (name == "ftheta") {
    if (n < 1 || n > 6)
      throw Error("ftheta expects 1 to 6 coefficients (c1..c6); got " + count_text(n));
    FThetaPolynomial f;
    f.c = {0, 0, 0, 0, 0, 0};
    std::copy(c.begin(), c.end(), f.c.begin());
    return f;
  }
  FisheyeMapping mapping;
  if (name == "equidistant")
    mapping = FisheyeMapping::equidistant;
  else if (name == "equisolid")
    mapping = FisheyeMapping::equisolid;
  else if (name == "stereographic")
    mapping = FisheyeMapping::stereographic;
  else if (name == "orthographic-fisheye")
    mapping = FisheyeMapping::orthographic;
  else
    throw Error("unknown lens model '" + name +
                "'; expected opencv, kannala-brandt, ftheta, equidistant, equisolid, "
                "stereographic or orthographic-fisheye");
  if (n != 0) {
    std::string message = name;
    message.append(" takes no coefficients; got ").append(count_text(n));
    throw Error(message);
  }
  return ClassicFisheye{mapping};
}

std::vector<double> lens_model_coefficients(const LensModel& model) {
  if (auto* d = std::get_if<PinholeDistortion>(&model)) {
    std::vector<double> a = {d->k1, d->k2, d->p1, d->p2, d->k3, d->k4,    d->k5,
                             d->k6, d->s1, d->s2, d->s3, d->s4, d->tau_x, d->tau_y};
    size_t used = 0;
    for (size_t i = 0; i < a.size(); ++i)
      if (a[i] != 0) used = i + 1;
    size_t count = used <= 5 ? 5 : used <= 8 ? 8 : used <= 12 ? 12 : 14;
    a.resize(count);
    return a;
  }
  if (auto* kb = std::get_if<KannalaBrandt>(&model)) return {kb->k1, kb->k2, kb->k3, kb->k4};
  if (auto* f = std::get_if<FThetaPolynomial>(&model)) {
    size_t used = 1;
    for (size_t i = 0; i < f->c.size(); ++i)
      if (f->c[i] != 0) used = i + 1;
    return std::vector<double>(f->c.begin(), f->c.begin() + used);
  }
  return {};
}

}  // namespace obscura

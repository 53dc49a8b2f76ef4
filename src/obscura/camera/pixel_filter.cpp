#include "obscura/camera/pixel_filter.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "obscura/camera/projection.h"  // Overloaded
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

double gaussian(double x, double sigma) {
  return std::exp(-x * x / (2 * sigma * sigma));
}

// Mitchell–Netravali on its natural support |x| ≤ 2.
double mitchell_1d(double x, double b, double c) {
  x = std::abs(x);
  if (x < 1)
    return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
  if (x < 2)
    return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x +
            (8 * b + 24 * c)) /
           6;
  return 0;
}

double evaluate_1d(const PixelFilter& filter, double x) {
  return std::visit(
      Overloaded{
          [&](const BoxFilter& f) { return std::abs(x) <= f.radius_px ? 1.0 : 0.0; },
          [&](const TentFilter& f) { return std::max(0.0, 1 - std::abs(x) / f.radius_px); },
          [&](const GaussianFilter& f) {
            if (std::abs(x) > f.radius_px) return 0.0;
            return std::max(0.0, gaussian(x, f.sigma_px) - gaussian(f.radius_px, f.sigma_px));
          },
          [&](const MitchellFilter& f) { return mitchell_1d(2 * x / f.radius_px, f.b, f.c); },
      },
      filter);
}

// Bins per axis for the tabulated filters: fine enough that the weights vary by well under 1 %.
constexpr int kTableBins = 256;

}  // namespace

double filter_radius_px(const PixelFilter& f) {
  return std::visit([](const auto& filter) { return filter.radius_px; }, f);
}

double evaluate(const PixelFilter& f, Vector2d offset) {
  return evaluate_1d(f, offset.x) * evaluate_1d(f, offset.y);
}

std::string_view filter_name(const PixelFilter& f) {
  return std::visit(Overloaded{
                        [](const BoxFilter&) { return "box"; },
                        [](const TentFilter&) { return "tent"; },
                        [](const GaussianFilter&) { return "gaussian"; },
                        [](const MitchellFilter&) { return "mitchell"; },
                    },
                    f);
}

PixelFilter make_pixel_filter(std::string_view name, double radius_px) {
  PixelFilter f;
  if (name == "box")
    f = BoxFilter{};
  else if (name == "tent")
    f = TentFilter{};
  else if (name == "gaussian")
    f = GaussianFilter{};
  else if (name == "mitchell")
    f = MitchellFilter{};
  else
    throw Error("pixel filter",
                "expected box, tent, gaussian or mitchell; got '" + std::string(name) + "'");
  if (radius_px != 0) std::visit([&](auto& filter) { filter.radius_px = radius_px; }, f);
  validate(f);
  return f;
}

void validate(const PixelFilter& f) {
  double r = filter_radius_px(f);
  // A wider filter spreads each sample over (2r)^2 pixels: at r = 16 already a thousand.
  if (!(r > 0) || !(r <= 16))
    throw Error("camera.filter_radius_px", "must be above 0 and at most 16; got " + number_text(r));
  if (auto* g = std::get_if<GaussianFilter>(&f); g && !(g->sigma_px > 0))
    throw Error("camera.filter_sigma_px", "must be positive; got " + number_text(g->sigma_px));
}

FilterSampler::FilterSampler(const PixelFilter& filter) : filter_(filter) {
  validate(filter);
  if (auto* box = std::get_if<BoxFilter>(&filter)) box_radius_px_ = box->radius_px;
  if (std::holds_alternative<BoxFilter>(filter) || std::holds_alternative<TentFilter>(filter))
    return;  // sampled exactly
  table_.radius = filter_radius_px(filter);
  table_.values.resize(kTableBins);
  table_.cdf.assign(kTableBins + 1, 0);
  double bin_width = 2 * table_.radius / kTableBins;
  for (int i = 0; i < kTableBins; ++i) {
    double x = -table_.radius + (i + 0.5) * bin_width;
    table_.values[i] = evaluate_1d(filter, x);
    table_.cdf[i + 1] = table_.cdf[i] + std::abs(table_.values[i]) * bin_width;
  }
  table_.integral = table_.cdf.back();
  for (double& c : table_.cdf) c /= table_.integral;
}

double FilterSampler::sample_axis(double u, double* pdf, double* value) const {
  int bins = int(table_.values.size());
  auto it = std::upper_bound(table_.cdf.begin(), table_.cdf.end(), u);
  int i = std::clamp(int(it - table_.cdf.begin()) - 1, 0, bins - 1);
  double bin_width = 2 * table_.radius / bins;
  double mass = table_.cdf[i + 1] - table_.cdf[i];
  double within = mass > 0 ? (u - table_.cdf[i]) / mass : 0.5;
  double x = -table_.radius + (i + within) * bin_width;
  *pdf = std::abs(table_.values[i]) / table_.integral;
  *value = table_.values[i];
  return x;
}

FilterSample FilterSampler::sample_other(Point2d u) const {
  if (auto* tent = std::get_if<TentFilter>(&filter_)) {
    // Inverse CDF of the unit tent on [−1, 1], per axis.
    auto sample_tent = [](double v) {
      return v < 0.5 ? std::sqrt(2 * v) - 1 : 1 - std::sqrt(2 - 2 * v);
    };
    return {{sample_tent(u.x) * tent->radius_px, sample_tent(u.y) * tent->radius_px}, 1.0};
  }
  // The table is piecewise constant, so f/pdf uses the bin's value: the weight's sign follows
  // the filter's lobes and its magnitude is the table's ∫|f| per axis.
  double pdf_x, pdf_y, f_x, f_y;
  double x = sample_axis(u.x, &pdf_x, &f_x);
  double y = sample_axis(u.y, &pdf_y, &f_y);
  return {{x, y}, (f_x * f_y) / (pdf_x * pdf_y)};
}

}  // namespace obscura

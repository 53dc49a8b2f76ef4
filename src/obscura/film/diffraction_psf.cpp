#include "obscura/film/diffraction_psf.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "obscura/color/primaries.h"
#include "obscura/color/spectral.h"
#include "obscura/film/fourier_plane.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

constexpr double kMillimetresPerNanometre = 1e-6;
constexpr int kLargestGrid = 4096;          // 4096² doubles: 128 MiB per buffer
constexpr double kLeastPupilSamples = 160;  // across the pupil's diameter
constexpr int kPupilSupersamples = 4;       // per axis, for the antialiased pupil edge
constexpr double kFadeStart = 0.75;         // of the radius
constexpr double kShortestNm = 380, kLongestNm = 780, kBandNm = 10;

struct Band {
  double wavelength_nm;
  std::array<double, 3> weight;  // per output channel
};

void validate(const DiffractionOptics& o, int radius_px) {
  if (!o.pupil) throw Error("diffraction PSF", "the pupil shape is missing");
  if (!(o.f_number > 0) || !std::isfinite(o.f_number))
    throw Error("diffraction PSF", "f-number must be positive; got " + number_text(o.f_number));
  if (!(o.pixel_width_mm > 0) || !(o.pixel_height_mm > 0) || !std::isfinite(o.pixel_width_mm) ||
      !std::isfinite(o.pixel_height_mm))
    throw Error("diffraction PSF", "pixel pitch must be positive; got " +
                                       number_text(o.pixel_width_mm) + " × " +
                                       number_text(o.pixel_height_mm) + " mm");
  if (radius_px < 1 || radius_px > 8192)
    throw Error("diffraction PSF",
                "radius must be in [1, 8192] pixels; got " + std::to_string(radius_px));
}

int even_fft_size(double at_least) {
  int n = fft_friendly_size(int(std::ceil(std::min(at_least, double(kLargestGrid)))));
  while (n % 2 != 0) n = fft_friendly_size(n + 1);
  return std::min(n, kLargestGrid);
}

// The pattern grid that resolves every band's PSF on these pixels: at least two samples per
// pixel at the longest wavelength (whose pattern is the widest, so its pixels the smallest in
// λ·N units), never coarser than ½ (aliasing), and wide enough to reach the kernel's edge at the
// shortest wavelength.
struct PatternGrid {
  int size = 0;
  double spacing = 0;
};
PatternGrid grid_for(const DiffractionOptics& o, int radius_px, double shortest_nm,
                     double longest_nm) {
  double smaller_pixel = std::min(o.pixel_width_mm, o.pixel_height_mm);
  double larger_pixel = std::max(o.pixel_width_mm, o.pixel_height_mm);
  double spacing =
      std::min(0.5, smaller_pixel / (2 * longest_nm * kMillimetresPerNanometre * o.f_number));
  // Tiny pixels under a wide pattern: keep the pupil resolved within the largest grid.
  spacing = std::max(spacing, kLeastPupilSamples / kLargestGrid);
  double reach =
      (radius_px + 1) * larger_pixel / (shortest_nm * kMillimetresPerNanometre * o.f_number);
  return {even_fft_size(std::max(2 * reach, kLeastPupilSamples) / spacing), spacing};
}

// How far (in pixels of the larger pitch) a grid reaches at the shortest wavelength.
double grid_reach_px(const DiffractionOptics& o, const PatternGrid& grid, double shortest_nm) {
  return (0.5 * grid.size - 1) * grid.spacing * shortest_nm * kMillimetresPerNanometre *
         o.f_number / std::max(o.pixel_width_mm, o.pixel_height_mm);
}

// Σ of the pattern over [0, i) × [0, j), (size + 1)² entries: the integral of the pattern, seen
// as constant over each sample's cell, up to any point is the bilinear interpolation of this.
struct SummedArea {
  int size;
  std::vector<double> sums;

  explicit SummedArea(const PupilPattern& p)
      : size(p.size), sums(size_t(p.size + 1) * (p.size + 1)) {
    const int n = size + 1;
    for (int j = 0; j < size; ++j) {
      double row = 0;
      for (int i = 0; i < size; ++i) {
        row += p.intensity[size_t(j) * size + i];
        sums[size_t(j + 1) * n + i + 1] = sums[size_t(j) * n + i + 1] + row;
      }
    }
  }
  // The integral over [0, x] × [0, y], in samples (cell i spans [i, i + 1]).
  double to(double x, double y) const {
    x = std::clamp(x, 0.0, double(size));
    y = std::clamp(y, 0.0, double(size));
    int i = std::min(int(x), size - 1), j = std::min(int(y), size - 1);
    double fx = x - i, fy = y - j;
    const double* r0 = &sums[size_t(j) * (size + 1) + i];
    const double* r1 = r0 + size + 1;
    return (r0[0] * (1 - fx) + r0[1] * fx) * (1 - fy) + (r1[0] * (1 - fx) + r1[1] * fx) * fy;
  }
};

// 1 inside kFadeStart of the radius, then cos² down to 0 at the radius.
double fade(double distance_over_radius) {
  if (distance_over_radius <= kFadeStart) return 1;
  if (distance_over_radius >= 1) return 0;
  double c =
      std::cos(0.5 * std::numbers::pi * (distance_over_radius - kFadeStart) / (1 - kFadeStart));
  return c * c;
}

// Σ over bands of weight × the band's PSF integrated over each pixel, faded and normalised per
// channel. Rows are independent and each sums its bands in order: thread-count independent.
Image sensor_psf(const DiffractionOptics& o, int radius_px, const std::vector<Band>& bands,
                 int channels, const std::atomic<bool>* cancel = nullptr) {
  auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  double shortest = bands.front().wavelength_nm, longest = shortest;
  for (const Band& b : bands) {
    shortest = std::min(shortest, b.wavelength_nm);
    longest = std::max(longest, b.wavelength_nm);
  }
  const PatternGrid grid = grid_for(o, radius_px, shortest, longest);
  const int side = 2 * radius_px + 1;
  Image psf(side, side, channels);
  const double larger_pixel = std::max(o.pixel_width_mm, o.pixel_height_mm);
  const double fade_radius = std::min(double(radius_px), grid_reach_px(o, grid, shortest));
  // When the fade ends within one pixel of the centre — pixels so wide that even the largest grid
  // ends inside the centre pixel (a very wide aperture, a film of a few pixels), or a radius of
  // one — it zeroes every other pixel: the kernel is the centre alone, known without the pattern
  // (whose largest grid costs seconds). There the Airy energy beyond half a pixel,
  // ≈ 2/(π²·ρ) at ρ = ½·pixel/(λ·N) ≥ 250, is under 1e-3 of the total.
  if (fade_radius * larger_pixel <= std::min(o.pixel_width_mm, o.pixel_height_mm)) {
    for (int c = 0; c < channels; ++c) psf.at(radius_px, radius_px, c) = 1;
    return psf;
  }
  PupilPattern pattern = pupil_pattern(o.pupil, grid.size, grid.spacing, cancel);
  if (pattern.intensity.empty()) return {};  // cancelled
  const double pattern_spacing = pattern.spacing;
  const SummedArea area(pattern);
  pattern = {};  // the table holds all that is needed
  std::vector<double> sums(size_t(side) * side * channels, 0.0);
  const double centre = area.size / 2 + 0.5;  // the cell of the pattern's centre spans [c, c + 1]
  tbb::parallel_for(tbb::blocked_range<int>(0, side), [&](const tbb::blocked_range<int>& rows) {
    std::vector<double> top(side + 1), bottom(side + 1);
    for (int row = rows.begin(); row < rows.end() && !cancelled(); ++row) {
      const int b = row - radius_px;
      double* out = &sums[size_t(row) * side * channels];
      for (const Band& band : bands) {
        double lambda_n = band.wavelength_nm * kMillimetresPerNanometre * o.f_number;
        double samples_per_x = o.pixel_width_mm / (lambda_n * pattern_spacing);
        double samples_per_y = o.pixel_height_mm / (lambda_n * pattern_spacing);
        double y0 = (b - 0.5) * samples_per_y + centre, y1 = (b + 0.5) * samples_per_y + centre;
        for (int e = 0; e <= side; ++e) {
          double x = (e - radius_px - 0.5) * samples_per_x + centre;
          top[e] = area.to(x, y0);
          bottom[e] = area.to(x, y1);
        }
        for (int column = 0; column < side; ++column) {
          double energy = bottom[column + 1] - bottom[column] - top[column + 1] + top[column];
          for (int c = 0; c < channels; ++c) out[column * channels + c] += band.weight[c] * energy;
        }
      }
      for (int column = 0; column < side; ++column) {
        double distance =
            std::hypot((column - radius_px) * o.pixel_width_mm, b * o.pixel_height_mm);
        double f = fade(distance / (fade_radius * larger_pixel));
        for (int c = 0; c < channels; ++c) out[column * channels + c] *= f;
      }
    }
  });
  if (cancelled()) return {};  // rows were left out
  for (int c = 0; c < channels; ++c) {
    double total = 0;
    for (size_t i = c; i < sums.size(); i += channels) total += sums[i];
    if (!(total > 0)) throw Error("diffraction PSF", "the pupil lets no light through");
    for (size_t i = c; i < sums.size(); i += channels) psf.data[i] = float(sums[i] / total);
  }
  return psf;
}

}  // namespace

PupilPattern pupil_pattern(const PupilShape& pupil, int size, double spacing,
                           const std::atomic<bool>* cancel) {
  auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  if (size < 16 || size % 2 != 0)
    throw Error("pupil pattern",
                "grid size must be even and at least 16; got " + std::to_string(size));
  if (!(spacing > 0 && spacing <= 0.5))
    throw Error("pupil pattern", "spacing must be in (0, 0.5]; got " + number_text(spacing));
  if (cancelled()) return {};
  FourierPlane plane(size, size);
  const int c = size / 2;
  const double radius = 0.5 * spacing * size;  // the pupil's radius in grid samples
  const int reach = std::min(c, int(std::ceil(radius)) + 1);
  const int first = c - reach, last = std::min(size, c + reach + 1);  // rows and columns
  auto inside = [&](double x, double y) {  // grid offsets from the centre; rows run down
    return pupil(x / radius, -y / radius);
  };
  // The shape at every cell corner, once: a cell whose four corners agree lies wholly on one
  // side of the edge of a convex shape many cells wide; only the others are supersampled.
  const int corners = last - first + 1;
  std::vector<char> corner(size_t(corners) * corners);
  tbb::parallel_for(tbb::blocked_range<int>(0, corners), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end() && !cancelled(); ++j)
      for (int i = 0; i < corners; ++i)
        corner[size_t(j) * corners + i] = inside(first + i - c - 0.5, first + j - c - 0.5);
  });
  tbb::parallel_for(tbb::blocked_range<int>(first, last), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j < rows.end() && !cancelled(); ++j)
      for (int i = first; i < last; ++i) {
        const char* top = &corner[size_t(j - first) * corners + (i - first)];
        const char* bottom = top + corners;
        int agree = top[0] + top[1] + bottom[0] + bottom[1];
        if (agree == 0 || agree == 4) {
          plane.row(j)[i] = agree == 4 ? 1.0 : 0.0;
          continue;
        }
        int hits = 0;
        for (int sy = 0; sy < kPupilSupersamples; ++sy)
          for (int sx = 0; sx < kPupilSupersamples; ++sx)
            hits += inside(i - c + (sx + 0.5) / kPupilSupersamples - 0.5,
                           j - c + (sy + 0.5) / kPupilSupersamples - 0.5);
        plane.row(j)[i] = double(hits) / (kPupilSupersamples * kPupilSupersamples);
      }
  });
  if (cancelled()) return {};
  plane.forward();  // about a second at the largest grid; FFTW cannot be interrupted
  if (cancelled()) return {};
  PupilPattern pattern{size, spacing, std::vector<double>(size_t(size) * size)};
  // |F|² everywhere from the half spectrum: F(−u, −v) is F(u, v)'s conjugate for a real pupil.
  tbb::parallel_for(tbb::blocked_range<int>(0, size), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v)
      for (int u = 0; u < size; ++u) {
        bool held = u <= size / 2;
        const std::complex<double> f =
            plane.spectrum_row(held ? v : (size - v) % size)[held ? u : size - u];
        pattern.intensity[size_t((v + c) % size) * size + (u + c) % size] = std::norm(f);
      }
  });
  double total = 0;
  for (double value : pattern.intensity) total += value;
  if (!(total > 0)) throw Error("pupil pattern", "the pupil lets no light through");
  for (double& value : pattern.intensity) value /= total;
  return pattern;
}

Image monochromatic_psf(const DiffractionOptics& optics, double wavelength_nm, int radius_px) {
  validate(optics, radius_px);
  if (!(wavelength_nm > 0) || !std::isfinite(wavelength_nm))
    throw Error("diffraction PSF",
                "wavelength must be positive; got " + number_text(wavelength_nm));
  Image psf = sensor_psf(optics, radius_px, {Band{wavelength_nm, {1, 0, 0}}}, 1);
  psf.channel_names = {"Y"};
  return psf;
}

Image rgb_psf(const DiffractionOptics& optics, int radius_px, const std::atomic<bool>* cancel) {
  validate(optics, radius_px);
  const Matrix3d rgb_from_xyz = xyz_from_rgb(primaries::kRec709).inverse();
  std::vector<Band> bands;
  for (double start = kShortestNm; start < kLongestNm; start += kBandNm) {
    Vec3d mean{};  // the band's mean x̄ȳz̄, from the observer's 1 nm table
    for (double nm = start; nm < start + kBandNm; nm += 1) {
      Vec3d xyz = cmf_xyz(nm + 0.5);
      for (int c = 0; c < 3; ++c) mean[c] += xyz[c] / kBandNm;
    }
    Vec3d rgb = rgb_from_xyz * mean;
    bands.push_back({start + 0.5 * kBandNm,
                     {std::max(0.0, rgb[0]), std::max(0.0, rgb[1]), std::max(0.0, rgb[2])}});
  }
  Image psf = sensor_psf(optics, radius_px, bands, 3, cancel);
  if (psf.data.empty()) return psf;  // cancelled
  psf.channel_names = {"R", "G", "B"};
  return psf;
}

}  // namespace obscura

// The colour pipeline on numpy arrays: conversions between every colour space
// (color/color_space.h), develop() (color/develop.h), spectral colours (color/spectral.h).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "arrays.h"
#include "bindings.h"
#include "color_settings.h"
#include "obscura/color/color_space.h"
#include "obscura/color/convert_pixels.h"
#include "obscura/color/develop.h"
#include "obscura/color/gamut.h"
#include "obscura/color/quantize.h"
#include "obscura/color/spectral.h"
#include "obscura/color/tonemap.h"
#include "obscura/math/error.h"

namespace obscura::python {

namespace {

// A library parse that throws obscura::Error for an unknown name, as a ValueError naming the
// keyword (a wrong name is a bad argument, not a failure of the engine).
template <typename Parse>
auto parse_name(const char* keyword, const std::string& text, Parse parse) {
  try {
    return parse(text);
  } catch (const Error& e) {
    throw py::value_error(std::string(keyword) + ": " + e.what());
  }
}

const ColorSpaceInfo& space_named(const char* keyword, const std::string& name) {
  std::optional<ColorSpaceInfo> found = find_color_space(name);
  if (!found) {
    std::string names;
    for (const ColorSpaceInfo& s : color_spaces()) names += (names.empty() ? "" : ", ") + s.name;
    throw py::value_error(std::string(keyword) + ": unknown colour space '" + name +
                          "'; expected one of " + names);
  }
  return color_space(name);
}

template <typename T>
py::array convert_typed(const py::array& in, const ColorSpaceInfo& from, const ColorSpaceInfo& to) {
  const size_t n = size_t(in.size()) / size_t(from.components);
  std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
  shape.back() = to.components;
  py::array_t<T> out(shape);
  const T* src = static_cast<const T*>(in.data());
  T* dst = out.mutable_data();
  const size_t fc = size_t(from.components), tc = size_t(to.components);
  py::gil_scoped_release release;
  // Chunks of pixels (a 4K row is 3840): each pixel's result depends on that pixel alone.
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
        convert_pixels(from, to, src + r.begin() * fc, dst + r.begin() * tc, r.size());
      });
  return out;
}

// f(x) for a scalar or an array of scalars, giving `components` values each: shape (...,
// components).
template <typename F>
py::array_t<double> map_scalars(const py::handle& x, const char* what, int components, F f) {
  std::vector<double> values;
  std::vector<py::ssize_t> shape;  // a number gives shape (components,)
  if (py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)) {
    values = {x.cast<double>()};
  } else {
    py::array in = checked_float_array(x, what, 0);
    values = as_doubles(in);
    shape.assign(in.shape(), in.shape() + in.ndim());
  }
  for (double v : values)
    if (!(v > 0) || !std::isfinite(v))
      throw py::value_error(std::string(what) + ": expected positive finite values, got " +
                            std::to_string(v));
  shape.push_back(components);
  std::vector<double> out(values.size() * size_t(components));
  for (size_t i = 0; i < values.size(); ++i) {
    std::array<double, 3> v = f(values[i]);
    for (int k = 0; k < components; ++k) out[i * components + k] = v[size_t(k)];
  }
  return vector_to_array(std::move(out), shape);
}

std::array<double, 3> as_array(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

DisplaySettings display_settings_from(const py::kwargs& kwargs) {
  DisplaySettings s;
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    if (name == "exposure") {
      s.exposure_ev = value.cast<float>();
    } else if (name == "tonemap") {
      s.tonemap.op = parse_name("tonemap", value.cast<std::string>(), parse_tone_map);
    } else if (name == "reinhard_white") {
      s.tonemap.reinhard_white = value.cast<float>();
    } else if (name == "display") {
      s.display = parse_name("display", value.cast<std::string>(), parse_display_space);
    } else if (name == "gamut") {
      s.gamut = parse_name("gamut", value.cast<std::string>(), parse_gamut_mapping);
    } else if (name == "bits") {
      s.bits = value.cast<int>();
    } else if (name == "dither") {
      s.dither = parse_name("dither", value.cast<std::string>(), parse_dither);
    } else {
      throw py::type_error("unexpected keyword argument '" + name +
                           "'; expected exposure, tonemap, reinhard_white, display, gamut, bits "
                           "or dither");
    }
  }
  try {
    validate(s);
  } catch (const Error& e) {
    throw py::value_error(e.what());
  }
  return s;
}

void bind_color(py::module_& m) {
  m.def(
      "color_spaces",
      [] {
        std::vector<std::string> names;
        for (const ColorSpaceInfo& s : color_spaces()) names.push_back(s.name);
        return names;
      },
      "The names of every colour space convert() knows (as `obscura color spaces` lists them).");

  m.def(
      "convert",
      [](const py::handle& values, const std::string& from, const std::string& to) {
        const ColorSpaceInfo& source = space_named("from_space", from);
        const ColorSpaceInfo& target = space_named("to_space", to);
        py::array in = checked_float_array(values, "convert(values)", source.components);
        return in.dtype().is(py::dtype::of<float>()) ? convert_typed<float>(in, source, target)
                                                     : convert_typed<double>(in, source, target);
      },
      py::arg("values"), py::arg("from_space"), py::arg("to_space"),
      "Converts colours between any two colour spaces (color_spaces()): `values` is float32 or "
      "float64 of shape (..., n) with n the source's components (3, CMYK 4); the result has the "
      "same dtype and leading shape. The same functions as `obscura color convert`.");

  m.def(
      "develop",
      [](const py::handle& pixels, const py::kwargs& kwargs) -> py::array {
        DisplaySettings settings = display_settings_from(kwargs);
        py::array in = checked_float_array(pixels, "develop(pixels)", 0, false);
        if (in.ndim() != 3 || (in.shape(2) != 3 && in.shape(2) != 4) ||
            !in.dtype().is(py::dtype::of<float>()))
          throw py::value_error(
              "develop(pixels): expected float32 of shape (height, width, 3 or 4)");
        LinearPixels view{static_cast<const float*>(in.data()), int(in.shape(1)), int(in.shape(0)),
                          int(in.shape(2))};
        DisplayImage image;
        {
          py::gil_scoped_release release;
          image = develop(view, settings);
        }
        std::vector<py::ssize_t> shape{image.height, image.width, image.channels};
        if (image.bits > 8) return vector_to_array(std::move(image.codes), shape);
        std::vector<uint8_t> bytes(image.codes.begin(), image.codes.end());
        return vector_to_array(std::move(bytes), shape);
      },
      py::arg("pixels"),
      "Develops linear Rec.709 pixels (float32 (H, W, 3|4)) into display codes as image files "
      "get them: exposure (EV), tonemap ('none', 'clamp', 'reinhard', 'aces', 'hable'), "
      "reinhard_white, display ('srgb', 'display-p3', 'rec2020-pq', 'rec2020-hlg'), gamut ('clip', "
      "'compress'), bits (1-16) and dither ('none', 'bayer', 'blue-noise'). Returns uint8 "
      "(bits <= 8) or uint16 codes of shape (H, W, C).");

  m.def(
      "wavelength_xyz",
      [](const py::handle& nm) {
        return map_scalars(nm, "wavelength_xyz(nm)", 3,
                           [](double v) { return as_array(cmf_xyz(v)); });
      },
      py::arg("nm"),
      "CIE 1931 2-degree XYZ of monochromatic light of unit power at `nm` (a number or an "
      "array; shape (..., 3)). 0 outside 360-830 nm.");
  m.def(
      "wavelength_lms",
      [](const py::handle& nm) {
        return map_scalars(nm, "wavelength_lms(nm)", 3,
                           [](double v) { return as_array(cone_lms(v)); });
      },
      py::arg("nm"),
      "Stockman-Sharpe 2-degree cone fundamentals L, M, S at `nm` (shape (..., 3)).");
  m.def(
      "blackbody_xyz",
      [](const py::handle& kelvin) {
        return map_scalars(kelvin, "blackbody_xyz(kelvin)", 3,
                           [](double v) { return as_array(blackbody_xyz(v)); });
      },
      py::arg("kelvin"),
      "XYZ (D65-relative, Y = 1) of a blackbody at `kelvin` (Planck's law; shape (..., 3)).");
  m.def(
      "chromaticity",
      [](const py::handle& xyz) {
        py::array in = checked_float_array(xyz, "chromaticity(xyz)", 3);
        std::vector<double> v = as_doubles(in);
        std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
        shape.back() = 2;
        std::vector<double> out(v.size() / 3 * 2);
        for (size_t i = 0; i < v.size() / 3; ++i) {
          Chromaticity c = chromaticity_of({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
          out[2 * i] = c.x, out[2 * i + 1] = c.y;
        }
        return vector_to_array(std::move(out), shape);
      },
      py::arg("xyz"), "CIE xy chromaticity of XYZ values (shape (..., 3) -> (..., 2)).");
  m.def(
      "planck_radiance", [](double nm, double kelvin) { return planck_radiance(nm, kelvin); },
      py::arg("nm"), py::arg("kelvin"),
      "Spectral radiance of a blackbody, W / (m^2 sr m), at `nm` and `kelvin`.");
}

}  // namespace obscura::python

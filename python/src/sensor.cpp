// The raw sensor from Python (docs/sensor.md): a rendered film captured by a sensor described by
// a dict of the JSON block's fields, written as a DNG or developed; metering a film.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "obscura/film/metering.h"
#include "obscura/io/dng_file.h"
#include "obscura/math/request_error.h"
#include "obscura/render/sensor_exposure.h"
#include "obscura/sensor/isp.h"
#include "obscura/sensor/sensor_capture.h"

namespace obscura::python {

namespace {

// The dict's fields over the defaults, as the JSON block and `--sensor` name them.
SensorSpec sensor_from(const py::object& fields) {
  SensorSpec spec;
  if (fields.is_none()) return spec;
  if (!py::isinstance<py::dict>(fields))
    throw RequestError("sensor", "expected a dict of sensor fields, e.g. {'cfa': 'RGGB'}");
  for (const auto& [key, value] : fields.cast<py::dict>()) {
    const std::string name = py::str(key);
    if (py::isinstance<py::str>(value))
      set_sensor_field(spec, name, value.cast<std::string>());
    else if (py::isinstance<py::bool_>(value) ||
             !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)))
      throw RequestError("sensor." + name, "expected a number");
    else if (py::isinstance<py::int_>(value) && name == "seed")
      spec.seed = value.cast<uint64_t>();
    else
      set_sensor_number(spec, name, value.cast<double>());
  }
  spec.validate();
  return spec;
}

RawCapture capture(const py::handle& film, const Camera& camera, const py::object& sensor,
                   uint64_t seed) {
  Image image = array_to_image(film, "film");
  const SensorSpec spec = sensor_from(sensor);
  const SensorExposure exposure = sensor_exposure(camera);
  py::gil_scoped_release release;
  return capture_raw(image, spec, exposure, seed);
}

std::vector<double> matrix_list(const Matrix3d& m) {
  std::vector<double> values;
  for (const auto& row : m.m) values.insert(values.end(), row.begin(), row.end());
  return values;
}

}  // namespace

void bind_sensor(py::module_& m) {
  m.def(
      "capture_raw",
      [](const py::handle& film, const Camera& camera, const py::object& sensor, uint64_t seed) {
        RawCapture c = capture(film, camera, sensor, seed);
        py::dict out;
        const py::ssize_t h = c.height, w = c.width;
        out["raw"] = vector_to_array(std::move(c.raw), {h, w});
        out["electrons"] = vector_to_array(std::move(c.electrons.data), {h, w});
        out["irradiance"] = vector_to_array(std::move(c.irradiance_lux.data), {h, w, 3});
        out["cfa"] = std::string(cfa_pattern_name(c.cfa));
        out["black_level"] = c.black_level;
        out["white_level"] = c.white_level;
        out["gain_dn_per_e"] = c.gain_dn_per_e;
        out["color_matrix_d65"] = matrix_list(c.response.color_matrix_d65);
        out["color_matrix_a"] = matrix_list(c.response.color_matrix_a);
        out["as_shot_neutral"] =
            std::vector<double>(c.response.neutral_d65.begin(), c.response.neutral_d65.end());
        return out;
      },
      py::arg("film"), py::arg("camera"), py::arg("sensor") = py::none(), py::arg("seed") = 0,
      "Captures a rendered film (linear Rec.709, (H, W, 3), as render() returns it) with a raw "
      "sensor: `sensor` is a dict of the JSON camera's sensor fields (cfa, pixel_pitch_um, "
      "full_well_e, read_noise_e, ...; docs/sensor.md), `camera` the camera it was rendered with "
      "(its shutter, f-number, ISO and exposure), `seed` the frame's temporal noise. Returns a "
      "dict: raw (uint16 DN, (H, W)), electrons (noise-free expected photoelectrons), irradiance "
      "(lux, (H, W, 3)), cfa, black_level, white_level, gain_dn_per_e, color_matrix_d65, "
      "color_matrix_a, as_shot_neutral.");

  m.def(
      "develop_raw",
      [](const py::handle& film, const Camera& camera, const py::object& sensor, uint64_t seed,
         const std::string& demosaic) {
        const DemosaicMethod method = parse_demosaic_method(demosaic);
        RawCapture c = capture(film, camera, sensor, seed);
        Image developed;
        {
          py::gil_scoped_release release;
          developed = develop_raw(c, method);
        }
        return image_to_array(std::move(developed));
      },
      py::arg("film"), py::arg("camera"), py::arg("sensor") = py::none(), py::arg("seed") = 0,
      py::arg("demosaic") = "malvar",
      "capture_raw, then the reference image pipeline: demosaic (bilinear or malvar), white "
      "balance and the colour-correction matrix, back to linear Rec.709 in the film's units.");

  m.def(
      "write_dng",
      [](const std::string& path, const py::handle& film, const Camera& camera,
         const py::object& sensor, uint64_t seed, bool linear, const std::string& demosaic,
         bool ground_truth) {
        DngWriteOptions options;
        options.linear = linear;
        options.demosaic = parse_demosaic_method(demosaic);
        options.ground_truth = ground_truth;
        RawCapture c = capture(film, camera, sensor, seed);
        py::gil_scoped_release release;
        return write_dng(path, c, options);
      },
      py::arg("path"), py::arg("film"), py::arg("camera"), py::arg("sensor") = py::none(),
      py::arg("seed") = 0, py::arg("linear") = false, py::arg("demosaic") = "malvar",
      py::arg("ground_truth") = true,
      "capture_raw, written as a DNG (CFA, or demosaiced LinearRaw with linear=True) with the "
      "raw mosaic, irradiance and noise-free electrons as OpenEXR beside it (x.raw.exr, "
      "x.irradiance.exr, x.electrons.exr). Returns the paths written, the DNG first.");

  m.def(
      "meter",
      [](const py::handle& film, const std::string& mode) {
        const MeteringMode metering = parse_metering_mode(mode);
        return metered_ev100(metered_luminance(array_to_image(film, "film"), metering));
      },
      py::arg("film"), py::arg("mode") = "average",
      "The EV100 a reflected-light meter (ISO 2720, K = 12.5) reads from a film in scene "
      "luminance (radiance mode, no compensation): average, center-weighted or spot.");
}

}  // namespace obscura::python

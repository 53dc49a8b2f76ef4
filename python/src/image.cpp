// Image files to and from numpy arrays (io/image_io.h).
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "color_settings.h"
#include "obscura/io/image_io.h"

namespace obscura::python {

void bind_image(py::module_& m) {
  m.def(
      "read_image",
      [](const std::string& path) {
        Image image;
        {
          py::gil_scoped_release release;
          image = read_image(path);
        }
        return image_to_array(std::move(image));
      },
      py::arg("path"),
      "Reads an image file (PNG, JPEG, EXR, HDR, TIFF, PFM, ...) as float32 (H, W, C) without "
      "decoding: 8/16-bit files give their codes scaled to [0, 1], float files their values.");

  m.def(
      "read_exr",
      [](const std::string& path) {
        ImageMetadata metadata;
        Image image;
        {
          py::gil_scoped_release release;
          image = read_exr_data(path, metadata);
        }
        py::dict attributes;
        for (const auto& [name, value] : metadata.attributes) attributes[py::str(name)] = value;
        if (!metadata.description.empty()) attributes["ImageDescription"] = metadata.description;
        std::vector<std::string> channels = image.channel_names;
        return py::make_tuple(image_to_array(std::move(image)), channels, attributes);
      },
      py::arg("path"),
      "Reads every channel of an OpenEXR file exactly as stored (NaN and Inf included). Returns "
      "(array float32 (H, W, C), channel names, string attributes).");

  m.def(
      "write_image",
      [](const std::string& path, const py::handle& pixels, const py::kwargs& develop) {
        ImageWriteOptions options;
        options.display = display_settings_from(develop);
        Image image = array_to_image(pixels, "write_image(pixels)");
        if (image.channels == 2)
          throw py::value_error("write_image(pixels): expected 1, 3 or 4 channels, got 2");
        check_output_path(path);
        py::gil_scoped_release release;
        write_image(path, image, options);
      },
      py::arg("path"), py::arg("pixels"),
      "Writes linear Rec.709 pixels (float32/float64, (H, W), (H, W, 3) or (H, W, 4)); the format "
      "follows the extension. EXR, HDR and PFM keep linear values; PNG, JPEG and TIFF are "
      "developed with the keyword arguments develop() takes (exposure, tonemap, display, gamut, "
      "bits, dither). Written atomically: a failure leaves no partial file.");
}

}  // namespace obscura::python

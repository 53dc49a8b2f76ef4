// Camera options shared by `obscura render` and `obscura camera`: pick a scene camera by name and
// override its parameters from the command line.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "obscura/camera/camera.h"
#include "obscura/scene/scene.h"

namespace obscura::app {

// Each field is set only when its option was given. Lengths in mm or m as named, angles in
// degrees, as on the command line.
struct CameraOverrides {
  std::optional<std::string> camera_name;
  // perspective | orthographic | spherical | fisheye | calibrated
  std::optional<std::string> projection;
  std::optional<double> fov_degrees, horizontal_fov_degrees, focal_length_mm;
  std::optional<std::string> sensor;  // "WxH" in mm
  std::optional<std::string> sensor_fit;
  std::optional<double> view_height_m;
  std::optional<double> f_number, focus_distance_m, aperture_rotation_degrees;
  std::optional<int> aperture_blades;
  std::optional<std::string> focus_breathing;  // on | off
  bool natural_vignetting = false;             // cos⁴
  std::optional<std::string> lens_barrel;      // "DIAMETER:DISTANCE" in mm (mechanical vignetting)
  std::optional<std::string> shutter;  // "OPEN:CLOSE" in seconds, fractions allowed (0:1/60)
  // "LINE_TIME[:READOUT]": a rolling shutter's line time in seconds and its readout order.
  std::optional<std::string> rolling_shutter;
  std::optional<double> iso, exposure_ev;
  std::optional<std::string> exposure_mode;
  std::optional<std::string> crop;  // "x0,y0,x1,y1"
  std::optional<std::string> filter;
  std::optional<double> filter_radius_px;
  std::optional<double> near_m, far_m;
  // Calibrated cameras (calibrated_camera_options.h).
  std::optional<std::string> intrinsics;        // "fx,fy,cx,cy[,skew]" in OpenCV pixels
  std::optional<std::string> calibration_size;  // "WxH": the image K is given for
  std::optional<std::string> distortion;        // "MODEL[:c1,c2,...]"
  std::optional<double> max_field_angle_degrees;
  std::optional<std::string> calibration;        // a calibration file
  std::optional<std::string> calibration_image;  // which image of a COLMAP or NeRF file
  // Lens-system cameras (lens_system_options.h).
  std::optional<std::string> lens;          // a built-in lens's name
  std::optional<std::string> lens_file;     // a prescription file
  std::optional<std::string> lens_coating;  // "none" | "quarter-wave[:INDEX[:NM]]"
};

void add_camera_options(CLI::App& command, CameraOverrides& overrides);

// The shutter --shutter gives, else the default one (a malformed value throws UsageError).
Shutter shutter_option(const CameraOverrides& overrides);

// The scene's camera named by --camera (or its only camera), with the overrides applied, at
// width × height pixels when given, validated. A malformed option value throws UsageError;
// an unknown camera or an invalid result throws obscura::Error.
Camera resolve_camera(const Scene& scene, const CameraOverrides& overrides,
                      std::optional<int> width_px = std::nullopt,
                      std::optional<int> height_px = std::nullopt);

}  // namespace obscura::app

// The camera a frame is rendered with, resolved in one place from what every door asks for: the
// scene's camera (by name), a calibration file, and the overrides the command line
// (`obscura render`, `obscura camera`) and the Python module give — so that the same request
// gives the same camera whichever door it came through, and an export describes the rendered
// images.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "obscura/camera/camera.h"
#include "obscura/scene/scene.h"

namespace obscura {

// What a user asks of the camera, by the command line's option names (docs/camera.md): each
// field set only when given. Lengths in mm or m as named, angles in degrees; text values in the
// command line's forms ("0:1/60", "36x24", "opencv:-0.28,0.07").
struct CameraRequest {
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
  // Calibrated cameras (render/calibrated_camera_request.h).
  std::optional<std::string> intrinsics;        // "fx,fy,cx,cy[,skew]" in OpenCV pixels
  std::optional<std::string> calibration_size;  // "WxH": the image K is given for
  std::optional<std::string> distortion;        // "MODEL[:c1,c2,...]"
  std::optional<double> max_field_angle_degrees;
  std::optional<std::string> calibration;        // a calibration file
  std::optional<std::string> calibration_image;  // which image of a COLMAP or NeRF file
  // Lens-system cameras (render/lens_system_request.h).
  std::optional<std::string> lens;          // a built-in lens's name
  std::optional<std::string> lens_file;     // a prescription file
  std::optional<std::string> lens_coating;  // "none" | "quarter-wave[:INDEX[:NM]]"
  // Placement (render/camera_placement.h): "X,Y,Z" each; the pose becomes a fixed one.
  std::optional<std::string> position, look_at, up;
  // The moment shown (--time): the shutter, its length kept, is centred on it.
  std::optional<double> time_s;
};

// The film's side when neither the request, a calibration file nor the scene file give it.
inline constexpr int kDefaultFilmSidePx = 512;

// The shutter the request gives (shutter), else the default one. A malformed value throws
// RequestError.
Shutter requested_shutter(const CameraRequest& request);

// The scene's camera named by camera_name (or its only camera), with the request applied,
// validated. Its film size, each side on its own, is the first given of: `width_px`/`height_px`
// (the command line's --width/--height, Python's width/height), a calibration file's image
// size, the scene file's render.width/height, kDefaultFilmSidePx. What the user should know (a
// film whose shape stretches a calibration's K) is added to `notes`. A malformed or out-of-range
// request value throws RequestError naming the option; an unknown camera, an unreadable
// calibration file or an invalid scene camera throws obscura::Error.
Camera resolve_camera(const Scene& scene, const CameraRequest& request,
                      std::optional<int> width_px = std::nullopt,
                      std::optional<int> height_px = std::nullopt,
                      std::vector<std::string>* notes = nullptr);

}  // namespace obscura

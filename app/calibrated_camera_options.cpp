#include "calibrated_camera_options.h"

#include "option_ranges.h"

namespace obscura::app {

void add_calibrated_camera_options(CLI::App& command, CameraOverrides& o) {
  const char* group = "Calibrated camera (K and lens model, as calibration toolboxes give them)";
  command
      .add_option("--intrinsics", o.intrinsics,
                  "K as fx,fy,cx,cy[,skew] in OpenCV pixels (pixel centres at integers) of the "
                  "film, or of --calibration-size; makes the camera calibrated")
      ->group(group);
  command
      .add_option("--calibration-size", o.calibration_size,
                  "WxH: the image --intrinsics are given for; K scales to the film")
      ->group(group);
  command
      .add_option("--distortion", o.distortion,
                  "MODEL[:c1,c2,...]: opencv (4, 5, 8, 12 or 14 coefficients in OpenCV's order), "
                  "kannala-brandt (4), ftheta (1 to 6), equidistant, equisolid, stereographic, "
                  "orthographic-fisheye")
      ->group(group);
  command
      .add_option("--max-field-angle", o.max_field_angle_degrees,
                  "The widest angle from the optical axis the lens sees, in degrees (100 for a "
                  "200° fisheye)")
      ->check(number_in(1e-6, 180))
      ->group(group);
  command
      .add_option("--calibration", o.calibration,
                  "Load K, distortion, image size (and pose) from an OpenCV .yaml/.json, a NeRF "
                  "transforms.json or a COLMAP model (folder, cameras.txt or images.txt)")
      ->group(group);
  command
      .add_option("--calibration-image", o.calibration_image,
                  "Which image of a COLMAP or NeRF file gives the pose (default: the first)")
      ->group(group);
}

}  // namespace obscura::app

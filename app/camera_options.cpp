#include "camera_options.h"

#include "calibrated_camera_options.h"
#include "obscura/math/value_limits.h"
#include "option_ranges.h"

namespace obscura::app {

void add_camera_options(CLI::App& command, CameraOverrides& o) {
  const char* group = "Camera (override the scene's camera)";
  command.add_option("--camera", o.camera_name, "Which of the scene's cameras to use, by name")
      ->group(group);
  command
      .add_option("--projection", o.projection,
                  "perspective, orthographic, spherical (equirectangular 360°), fisheye or "
                  "calibrated (K and a lens model: --intrinsics, --distortion, --calibration)")
      ->group(group);
  command
      .add_option("--fov", o.fov_degrees,
                  "Vertical field of view in degrees (glTF's yfov); fisheye: the circle's angle")
      ->check(number_in(0, 360))
      ->group(group);
  command.add_option("--hfov", o.horizontal_fov_degrees, "Horizontal field of view in degrees")
      ->check(number_in(0, 360))
      ->group(group);
  command.add_option("--focal-length", o.focal_length_mm, "Lens focal length in mm")
      ->check(number_in(0, 1e6))
      ->group(group);
  command.add_option("--sensor", o.sensor, "Sensor size WxH in mm, e.g. 36x24")->group(group);
  command.add_option("--sensor-fit", o.sensor_fit, "auto, horizontal or vertical (as Blender)")
      ->group(group);
  // Twice the ±1e7 m world bound: the view's half height is a ray origin's offset from the
  // camera. (A wide image's half width is checked by Camera::validate.)
  command.add_option("--view-height", o.view_height_m, "Orthographic view height in m")
      ->check(number_in(0, 2 * kMaxWorldCoordinateM))
      ->group(group);
  command.add_option("--fstop", o.f_number, "Aperture f-number N; turns on depth of field")
      ->check(number_in(0, 1e4))
      ->group(group);
  command
      .add_option("--focus-distance", o.focus_distance_m,
                  "Focus distance in m; turns on depth of field")
      ->check(number_in(0, 1e12))
      ->group(group);
  command
      .add_option("--aperture-blades", o.aperture_blades,
                  "Aperture blades (0 = circle, >= 3 = polygon bokeh); turns on depth of field")
      ->check(integer_in(0, 64))
      ->group(group);
  command
      .add_option("--focus-breathing", o.focus_breathing,
                  "on (default): the sensor moves to the image distance as a real lens focuses; "
                  "off: the field of view stays fixed (Blender Cycles' and pbrt's convention)")
      ->group(group);
  command
      .add_flag("--natural-vignetting", o.natural_vignetting,
                "Thin lens: cos^4 falloff of the light towards the image corners")
      ->group(group);
  command
      .add_option("--lens-barrel", o.lens_barrel,
                  "Thin lens: mechanical vignetting by a barrel opening DIAMETER:DISTANCE (mm, "
                  "in front of the aperture; diameter >= the aperture's): cat-eye bokeh, darker "
                  "corners")
      ->group(group);
  command
      .add_option("--aperture-rotation", o.aperture_rotation_degrees,
                  "Rotation of the aperture polygon in degrees")
      ->check(number_in(-360, 360))
      ->group(group);
  command.add_option("--shutter", o.shutter, "Shutter OPEN:CLOSE in seconds, e.g. 0:1/60")
      ->group(group);
  command
      .add_option("--rolling-shutter", o.rolling_shutter,
                  "Rolling shutter LINE_TIME[:READOUT]: seconds between sensor lines (fractions "
                  "allowed, 1/30000) and top-to-bottom (default), bottom-to-top, left-to-right or "
                  "right-to-left; 0: a global shutter")
      ->group(group);
  command.add_option("--iso", o.iso, "Film speed; selects the physical exposure")
      ->check(number_in(0, 1e7))
      ->group(group);
  command.add_option("--exposure", o.exposure_ev, "Exposure compensation in EV (stops)")
      ->check(number_in(-kMaxExposureEv, kMaxExposureEv))
      ->group(group);
  command
      .add_option("--exposure-mode", o.exposure_mode,
                  "radiance (unscaled, the default) or physical (time x ISO / N^2)")
      ->group(group);
  command.add_option("--crop", o.crop, "Render only x0,y0,x1,y1 (fractions, top-left origin)")
      ->group(group);
  command.add_option("--filter", o.filter, "Pixel filter: box, tent, gaussian or mitchell")
      ->group(group);
  command.add_option("--filter-radius", o.filter_radius_px, "Pixel filter radius in pixels")
      ->check(number_in(0.01, kMaxFilterRadiusPx))
      ->group(group);
  command.add_option("--near", o.near_m, "Near clipping plane in m")
      ->check(number_in(0, 1e12))
      ->group(group);
  command.add_option("--far", o.far_m, "Far clipping plane in m (inf: none)")
      ->check(number_in_or_infinity(0, 1e15))
      ->group(group);
  command
      .add_option("--lens", o.lens,
                  "A real lens traced surface by surface: double-gauss-50mm, telephoto-250mm or "
                  "fisheye-10mm (--fstop stops it down, --focus-distance focuses it)")
      ->group(group);
  command.add_option("--lens-file", o.lens_file, "A lens prescription file (see docs/camera.md)")
      ->group(group);
  command
      .add_option("--lens-coating", o.lens_coating,
                  "A lens system's anti-reflection coating, what its ghost flares reflect: none, "
                  "quarter-wave (MgF2, n 1.38, at 550 nm; the default) or quarter-wave:INDEX[:NM]")
      ->group(group);
  command
      .add_option("--position", o.position,
                  "Place the camera's centre at X,Y,Z (m); alone, its orientation is kept")
      ->group(group);
  command
      .add_option("--look-at", o.look_at,
                  "Turn the camera to look at the point X,Y,Z (m), its up towards --up")
      ->group(group);
  command
      .add_option("--up", o.up,
                  "The direction X,Y,Z the image's up turns towards (default with --look-at: "
                  "world +Y); alone, rolls the camera about its view direction")
      ->group(group);
  add_calibrated_camera_options(command, o);
}

}  // namespace obscura::app

// The camera: one description that drives both renderers. The tracer asks it for rays
// (generate_ray), the rasterizer for matrices (view_matrix, projection_matrix), and both map
// back with project / unproject; all of them agree on which pixel a point lands on.
//
// Spaces: world is right-handed, Y-up. Camera space: X right, Y up, looking down −Z, origin at
// the lens centre. Raster space: pixels of the full image, (0, 0) the top-left corner, pixel
// centres at half-integers, y down. NDC: OpenGL's cube [−1, 1]³, near → −1, far → +1.
// The "screen window" is the film's rectangle in camera space: on the plane z = −1 for a
// perspective camera (so its coordinates are tangents of angles), at any depth for an
// orthographic one (in metres).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "obscura/camera/animated_transform.h"
#include "obscura/camera/exposure.h"
#include "obscura/camera/film_geometry.h"
#include "obscura/camera/focused_lens_system.h"
#include "obscura/camera/projection.h"
#include "obscura/camera/shutter.h"
#include "obscura/camera/thin_lens.h"
#include "obscura/math/matrix4.h"
#include "obscura/math/ray.h"
#include "obscura/math/transform.h"
#include "obscura/math/vector.h"

namespace obscura {

// A primary ray in double precision (the tracer converts it with to_ray()).
struct CameraRay {
  Point3d origin;
  Vector3d direction;  // unit length
  // The stretch of the ray between the near and far clipping planes (perspective and
  // orthographic: planes of constant depth; spherical cameras: distances).
  double t_min = 0, t_max = 0;
  double time_s = 0;
  // What the ray carries of the scene's radiance to the film: 1 for an ideal camera; less where
  // the optics lose light on the way to this film point (vignetting, a lens system's relative
  // illumination), so a renderer multiplies the ray's radiance by it.
  double weight = 1;

  Ray to_ray() const;
};

// Where a world point lands on the film.
struct FilmProjection {
  Point2d film_point;  // raster coordinates (pixels)
  // Perspective, orthographic and calibrated pinhole: depth in front of the camera, along its −Z
  // axis (the rasterizer's eye depth). Spherical and calibrated fisheye cameras: distance from
  // the camera.
  double depth_m = 0;
};

struct ScreenWindow {
  double x_min = -1, x_max = 1, y_min = -1, y_max = 1;
};

class PreparedCamera;

struct Camera {
  std::string name;
  AnimatedTransform world_from_camera;  // rigid motion over the shutter interval
  Projection projection = Perspective{};
  // Clipping planes: 0 < near < far (orthographic: 0 ≤ near); far may be infinite.
  double near_m = 0.1, far_m = 1000;
  ThinLens lens;  // depth of field (perspective only) and the f-number of the physical exposure
  Shutter shutter;
  Exposure exposure;
  FilmGeometry film;

  // Throws obscura::Error naming the first invalid parameter and its value.
  void validate() const;

  // --- the tracer ---
  // The ray through raster point `film_point` at lens sample `lens_sample` ∈ [0,1)² (ignored
  // without depth of field; (½, ½) is the lens centre) at time `time_s`. Nothing when the film
  // point sees nothing (outside a fisheye's image circle).
  std::optional<CameraRay> generate_ray(Point2d film_point, Point2d lens_sample = {0.5, 0.5},
                                        double time_s = 0) const;
  // The same rays with the per-render constants computed once: for renderers, which ask for
  // many rays from an unchanging camera.
  // `for_many_rays` also tabulates a calibrated camera's exact inverse lens map every few pixels
  // as each ray's starting point (render loops: a few thousand solves once, then a Newton step or
  // two per ray instead of a full solve; the rays are the same to the solver's tolerance).
  PreparedCamera prepare(bool for_many_rays = false) const;
  // The inverse of generate_ray through the lens centre, for every projection: where `world`
  // lands on the film at time `time_s`; nothing when it is not visible (behind the camera,
  // outside the near/far range, off the film or outside a fisheye's circle).
  std::optional<FilmProjection> project(Point3d world, double time_s = 0) const;
  // The world point at raster `film_point` and `depth_m` (as FilmProjection::depth_m); nothing
  // outside a fisheye's circle. unproject(project(p)) = p.
  std::optional<Point3d> unproject(Point2d film_point, double depth_m, double time_s = 0) const;

  // --- the rasterizer ---
  Matrix4 view_matrix(double time_s = 0) const;  // camera_from_world
  // clip_from_camera with OpenGL's conventions (glFrustum / glOrtho, off-centre for lens
  // shift; far = ∞ gives the infinite-far limit). Throws obscura::Error for spherical
  // projections, which have no matrix (see has_projection_matrix).
  Matrix4 projection_matrix() const;
  bool has_projection_matrix() const;
  // The viewport: NDC (x, y) → raster (x right, y down, pixels); z passes through.
  Matrix4 raster_from_ndc() const;
  // Circle of confusion for a point at `depth_m`, in pixels (0 without depth of field).
  double circle_of_confusion_px(double depth_m) const;

  // --- derived quantities ---
  ScreenWindow screen_window() const;  // perspective and orthographic
  // Focal length (perspective), else 0; image distance = where the sensor sits behind the lens:
  // the focal length, or v = f·S_f/(S_f − f) with depth of field.
  double focal_length_mm() const;
  double image_distance_mm() const;
  Vector2d film_size_mm() const;  // perspective: the sensor area the image covers
  // Horizontal and vertical field of view, in degrees: the angle the screen window subtends
  // (perspective), the full 360 × 180 (equirectangular), the circle's angle on each axis
  // (fisheye), 0 (orthographic).
  Vector2d fov_degrees() const;
  double lens_radius_m() const;  // 0 without depth of field
  // Whether rays depend on the lens sample (depth of field, or a lens system's pupil).
  bool uses_lens_samples() const;
  // A lens-system camera's settings for its FocusedLensSystem: focus, iris, sensor size.
  LensSettings lens_system_settings() const;
  double f_number() const;
  double exposure_scale() const;  // see exposure.h
  // The thin lens's vignetting at raster point `film_point` (vignetting.h): cos⁴θ if natural,
  // times the share of the aperture the barrel leaves if mechanical; the mean of the tracer's
  // ray weights over the lens there. 1 without vignetting or for other projections.
  double relative_illumination(Point2d film_point) const;

  // --- rolling shutter (shutter.h) ---
  // How long after the shutter opens the sensor line through raster point `film_point` starts
  // exposing: line_time × the line's position in readout order, measured from the first line's
  // centre and continuous between lines (so a pixel centre gets its line's exact delay), clamped
  // to the image. 0 for a global shutter.
  double readout_delay_s(Point2d film_point) const;
  // The interval in which some line is exposing: [open, close + (lines − 1) · line_time].
  Shutter exposure_interval() const;

  Point2d window_from_raster(Point2d raster) const;
  Point2d raster_from_window(Point2d window) const;
};

// A camera ready to render: what the per-pixel and per-sample questions need that does not
// change from one to the next (the screen window, the lens radius, the focal length, the
// transform of a camera that does not move, a calibrated camera's lens map), computed once.
// Recomputing them per ray was a tenth of the tracer's time per sample on simple scenes.
// Its answers are Camera's bit for bit (Camera::generate_ray, project and unproject are these,
// prepared per call). Refers to the camera, which must outlive it and not change while in use.
class PreparedCamera {
 public:
  explicit PreparedCamera(const Camera& camera, bool for_many_rays = false);
  const Camera& camera() const { return *camera_; }

  // `wavelength_nm` matters only to a camera whose optics disperse (see disperses()): a lens
  // system with glasses of finite Abbe number bends each wavelength differently (chromatic
  // aberration). Other cameras ignore it; the default is the d line the lens data are given at.
  std::optional<CameraRay> generate_ray(Point2d film_point, Point2d lens_sample = {0.5, 0.5},
                                        double time_s = 0,
                                        double wavelength_nm = kWavelengthD_nm) const;
  // Whether the ray generate_ray returns depends on the wavelength: a spectral renderer then
  // traces one wavelength per camera ray.
  bool disperses() const { return disperses_; }
  std::optional<FilmProjection> project(Point3d world, double time_s = 0) const;
  std::optional<Point3d> unproject(Point2d film_point, double depth_m, double time_s = 0) const;
  // As Camera's; the window ones for perspective and orthographic cameras only.
  Point2d window_from_raster(Point2d raster) const;
  Point2d raster_from_window(Point2d window) const;
  double circle_of_confusion_px(double depth_m) const;
  double relative_illumination(Point2d film_point) const;
  Transform world_from_camera(double time_s) const;

 private:
  const Camera* camera_;
  ScreenWindow window_;  // perspective and orthographic
  double window_width_ = 0, window_height_ = 0;
  double width_px_ = 0, height_px_ = 0;
  double lens_radius_m_ = 0;
  double focal_length_mm_ = 0, film_width_mm_ = 0;  // what the circle of confusion needs
  double aperture_radius_mm_ = 0;                   // what vignetting needs
  ApertureChords aperture_chords_;
  const Transform* fixed_world_from_camera_ = nullptr;     // a camera that does not move
  std::optional<LensMap> lens_map_;                        // a calibrated camera's
  std::shared_ptr<const FocusedLensSystem> focused_lens_;  // a lens-system camera's
  bool disperses_ = false;
  double sensor_width_mm_ = 0, sensor_height_mm_ = 0;  // a lens-system camera's
  Point2d image_mm_from_raster(Point2d raster) const;
  Point2d raster_from_image_mm(Point2d image) const;
  // Its undistorted points (X/Z, Y/Z) at raster points every kStartSpacing pixels (NaN where
  // none): the inverse's starting guesses, bilinearly interpolated.
  static constexpr double kStartSpacing = 8;
  int start_columns_ = 0, start_rows_ = 0;
  std::vector<Point2d> starts_;
  std::optional<Point2d> start_at(Point2d film_point) const;
  // The share of the aperture the lens barrel leaves at window point w (1 without a barrel).
  double relative_barrel_share(Point2d window) const;
};

}  // namespace obscura

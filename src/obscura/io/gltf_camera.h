// glTF 2.0 cameras ↔ Obscura cameras, for scene loaders and for reporting.
//
// glTF's cameras match Obscura's frame (Y-up, looking down −Z), so a camera node's world
// transform is world_from_camera as is (glTF leaves a scaled camera node undefined; loaders
// should drop the scale). glTF describes no lens, shutter or film: those keep their defaults.
#pragma once

#include <optional>

#include "obscura/camera/camera.h"

namespace obscura {

// camera.perspective
struct GltfPerspective {
  double yfov_radians = 0.8;           // vertical field of view, in (0, π)
  std::optional<double> aspect_ratio;  // width / height; absent: the viewport's
  double znear_m = 0.1;                // > 0
  std::optional<double> zfar_m;        // absent: infinite
};

// camera.orthographic (xmag, ymag are half the view's width and height)
struct GltfOrthographic {
  double xmag_m = 1, ymag_m = 1;  // > 0 (glTF forbids 0 and discourages negatives)
  double znear_m = 0.1;           // ≥ 0
  double zfar_m = 100;            // > znear
};

// A vertical-fit perspective camera with exactly yfov. With an aspect ratio, the film keeps
// `width_px` and takes height = round(width / aspect); without, `width_px` × `height_px`.
Camera from_gltf_perspective(const GltfPerspective& g, int width_px = 512, int height_px = 512);
// An orthographic camera 2·xmag × 2·ymag metres; the film is `width_px` wide with the height
// that keeps pixels square: round(width · ymag / xmag).
Camera from_gltf_orthographic(const GltfOrthographic& g, int width_px = 512);

// The glTF description of a perspective or orthographic camera (yfov: the vertical angle the
// film subtends; aspect: the film's physical aspect). Throws obscura::Error for other kinds.
struct GltfCamera {
  std::optional<GltfPerspective> perspective;
  std::optional<GltfOrthographic> orthographic;
};
GltfCamera to_gltf(const Camera& camera);

// Blender's camera settings for the same camera (Camera data block + depth of field).
struct BlenderCamera {
  const char* type = "PERSP";  // PERSP, ORTHO, PANO; NONE: Blender has no such camera
  double lens_mm = 50, sensor_width_mm = 36, sensor_height_mm = 24;
  const char* sensor_fit = "AUTO";  // AUTO, HORIZONTAL, VERTICAL
  double shift_x = 0, shift_y = 0;
  double ortho_scale = 0;  // ORTHO: the larger of the view's width and height
  double clip_start_m = 0.1, clip_end_m = 1000;
  bool use_dof = false;
  double fstop = 8, focus_distance_m = 10;
  int aperture_blades = 0;
  double aperture_rotation_degrees = 0;
  const char* panorama_type = "";  // PANO: EQUIRECTANGULAR or FISHEYE_EQUIDISTANT
  double fisheye_fov_degrees = 0;
};
BlenderCamera to_blender(const Camera& camera);

}  // namespace obscura

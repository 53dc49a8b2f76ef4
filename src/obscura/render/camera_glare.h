// Diffraction glare for a camera: the camera's aperture, working f-number and pixel pitch handed
// to film/'s PSF as plain numbers (film/ may not include camera/), and the glare applied to a
// rendered frame. Used by both renderers' callers (the command line, the Python module) on the
// assembled HDR frame, before develop.
#pragma once

#include "obscura/camera/camera.h"
#include "obscura/film/diffraction_psf.h"
#include "obscura/film/glare.h"
#include "obscura/film/image.h"
#include "obscura/render/frame_finish.h"

namespace obscura {

// The pupil is the camera's aperture (blades and rotation); the working f-number is the image
// distance over the aperture diameter (N at infinity focus, a little more focused close; a lens
// system's f-number); the pitch is the sensor area the image covers over its pixels. Throws
// obscura::Error for other cameras (no sensor to measure the pixels on).
DiffractionOptics diffraction_optics(const Camera& camera);

// The glare as the numbers finishing needs (render/frame_finish.h): the camera's aperture and
// diffraction_optics' f-number and pixel pitch, with the settings (validated).
GlareFinish glare_finish(const Camera& camera, const GlareSettings& settings);

// The camera's colour PSF with the settings' strength applied.
Image glare_psf(const Camera& camera, const GlareSettings& settings);

// Convolves `image` (linear RGB, the camera's crop) with glare_psf(camera, settings).
void apply_glare(Image& image, const Camera& camera, const GlareSettings& settings);

}  // namespace obscura

// An automatic exposure program, as a camera's "P" mode picks its settings: given the EV100 the
// meter asks for (less any compensation), choose f-number N, exposure time t and ISO S with
//   log₂(N² / t · 100 / S) = EV100
// exactly. The program line splits the EV evenly between aperture (Av = log₂ N²) and time
// (Tv = log₂ 1/t) within f/1.4–f/16 and 1/8000 s at the fast end; below 1/30 s (hand-held) it
// opens the aperture first, then raises the ISO up to 6400, then lengthens the exposure. A
// fixed f-number (a lens system's iris) makes it shutter-and-ISO only (aperture priority).
#pragma once

#include <optional>

namespace obscura {

struct ExposureSettings {
  double f_number = 8;
  double exposure_time_s = 1.0 / 60;
  double iso = 100;
};

// Precondition: target_ev100 finite. fixed_f_number > 0 when given.
ExposureSettings program_exposure(double target_ev100,
                                  std::optional<double> fixed_f_number = std::nullopt);

}  // namespace obscura

// The CIE and CVRL tables Obscura's spectral colour is built on (copied into data/color/ with
// their source note, compiled into the library by cmake/embed_color_data.cmake):
//   - CIE 1931 2° colour matching functions x̄ ȳ z̄, 360–830 nm at 1 nm;
//   - CIE standard illuminant D65, relative SPD, 300–830 nm at 1 nm;
//   - Stockman & Sharpe (2000) 2° cone fundamentals L M S (linear energy, peak 1), 390–830 nm.
#pragma once

#include <cstddef>
#include <vector>

namespace obscura {

// A table sampled every 1 nm from `first_nm`; `columns` values per row.
struct SpectralTable {
  int first_nm = 0;
  int columns = 0;
  std::vector<double> values;  // row-major

  int rows() const { return columns ? int(values.size()) / columns : 0; }
  int last_nm() const { return first_nm + rows() - 1; }
  double at(int row, int column) const { return values[size_t(row) * columns + column]; }
};

const SpectralTable& cie1931_cmf();          // columns x̄, ȳ, z̄
const SpectralTable& cie_d65_spd();          // one column, 100 at 560 nm
const SpectralTable& stockman_sharpe_lms();  // columns l̄, m̄, s̄

}  // namespace obscura

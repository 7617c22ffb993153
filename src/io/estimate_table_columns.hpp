// The columns of the table `frictionlab estimate LOG...` writes that say how a row was measured
// (which log, how many periods, the errors the rig computes, why a log failed): the readers of
// measurement tables (compare --measured, fit) read past them, so the table feeds both as it is.
// Its `status` column marks rows whose log gave no period ("failed"): those are left out.
#pragma once

#include <array>
#include <string_view>

namespace fl {

inline constexpr std::array<std::string_view, 7> kEstimateTableNoteColumns = {"log",
                                                                              "period_std",
                                                                              "periods_used",
                                                                              "periods_discarded",
                                                                              "mu_k_err_worst",
                                                                              "mu_k_err_quadrature",
                                                                              "error"};

inline bool is_estimate_table_note_column(std::string_view name) {
  for (std::string_view c : kEstimateTableNoteColumns)
    if (c == name) return true;
  return false;
}

}  // namespace fl

#include "lab/logs/log_table_fields.hpp"

#include "text/utf8.hpp"

namespace fl {
namespace {

// A text a row holds, a file name that is not UTF-8 escaped (text/utf8.hpp); none when empty.
FieldValue text_or_none(const std::string& text) {
  return text.empty() ? FieldValue() : FieldValue::text(escape_invalid_utf8(text));
}

}  // namespace

const std::vector<LogTableField>& log_table_fields() {
  using R = const LogTableRow&;
  using V = FieldValue;
  using T = FieldType;
  constexpr const char* kFailed = "the log gave no period (`status` is `failed`)";
  static const std::vector<LogTableField> fields = {
      {.json = "label",
       .csv = "label",
       .type = T::kText,
       .meaning = "the log's name (its file's, or its sidecar's `label`)",
       .get = [](R r) { return V::text(escape_invalid_utf8(r.label)); }},
      {.json = "log",
       .csv = "log",
       .type = T::kText,
       .meaning = "the file read",
       .get = [](R r) { return V::text(escape_invalid_utf8(r.log)); }},
      {.json = "sidecar",
       .type = T::kText,
       .meaning = "the sidecar read",
       .null_when = "the log has no sidecar",
       .get = [](R r) { return text_or_none(r.sidecar); }},
      {.json = "status",
       .csv = "status",
       .type = T::kText,
       .meaning = "`ok`, or `failed` when the log gave no period",
       .get = [](R r) { return V::text(r.status); }},
      {.json = "spacing_m",
       .csv = "rollers.spacing",
       .unit = "m",
       .meaning = "l, the rollers' spacing the log was taken at (its sidecar's, else the request's "
                  "`spacing`)",
       .get = [](R r) { return V::number(r.set_up.spacing); },
       .csv_unit = " m"},
      {.json = "spacing_err_m",
       .csv = "spacing_err",
       .unit = "m",
       .meaning = "dl, its uncertainty",
       .get = [](R r) { return V::number(r.set_up.spacing_err); },
       .csv_unit = " m"},
      {.json = "gravity_m_s2",
       .unit = "m/s^2",
       .meaning = "g used for mu_k",
       .get = [](R r) { return V::number(r.set_up.gravity); }},
      {.json = "material",
       .csv = "plate.material",
       .type = T::kText,
       .meaning = "the plate's material, a key of the paper's Table I",
       .null_when = "neither the sidecar nor the request (`material`) names one",
       .get = [](R r) { return text_or_none(r.material.value_or("")); }},
      {.json = "temperature_k",
       .csv = "friction.temperature",
       .unit = "K",
       .meaning = "the rollers' temperature",
       .null_when = "neither the sidecar nor the request (`temperature`) gives one",
       .get = [](R r) { return V::number(r.temperature); },
       .csv_unit = " K"},
      {.json = "geometry",
       .type = T::kText,
       .meaning = "`one-pulse` or `pair`: pulses per period",
       .null_when = kFailed,
       .get = [](R r) { return text_or_none(r.geometry); }},
      {.json = "period_s",
       .csv = "period",
       .unit = "s",
       .meaning = "T, the mean accepted period",
       .null_when = kFailed,
       .get = [](R r) { return V::number(r.period); }},
      {.json = "period_err_s",
       .csv = "period_err",
       .unit = "s",
       .meaning = "the standard error of that mean: the uncertainty a fit or a comparison weighs "
                  "the row by",
       .null_when = kFailed,
       .get = [](R r) { return V::number(r.period_err); }},
      {.json = "period_std_s",
       .csv = "period_std",
       .unit = "s",
       .meaning = "dT, the accepted periods' standard deviation (the paper's)",
       .null_when = kFailed,
       .get = [](R r) { return V::number(r.period_std); }},
      {.json = "periods_used",
       .csv = "periods_used",
       .type = T::kInteger,
       .meaning = "N, the accepted periods",
       .null_when = kFailed,
       .get = [](R r) { return V::whole(r.periods_used); }},
      {.json = "periods_discarded",
       .csv = "periods_discarded",
       .type = T::kInteger,
       .meaning = "rejected periods: outliers and periods at broken turning points",
       .null_when = kFailed,
       .get = [](R r) { return V::whole(r.periods_discarded); }},
      {.json = "mu_k",
       .csv = "mu_k",
       .meaning = "mu_k through the paper's (thin) formula",
       .null_when = kFailed,
       .get = [](R r) { return V::number(r.mu_k); }},
      {.json = "mu_k_err_worst",
       .csv = "mu_k_err_worst",
       .meaning = "d mu_k, the paper's worst case: mu_k (dl/l + 2 dT/T)",
       .null_when = kFailed,
       .get = [](R r) { return V::number(r.mu_k_err_worst); }},
      {.json = "mu_k_err_quadrature",
       .csv = "mu_k_err_quadrature",
       .meaning = "d mu_k in quadrature: mu_k sqrt((dl/l)^2 + (2 dT/T)^2)",
       .null_when = kFailed,
       .get = [](R r) { return V::number(r.mu_k_err_quadrature); }},
      {.json = "error",
       .csv = "error",
       .type = T::kText,
       .meaning = "why the log gave no period, located in it",
       .null_when = "the log gave a period",
       .get = [](R r) { return text_or_none(r.error); }},
  };
  return fields;
}

}  // namespace fl

// frictionlab.paper_table: the paper's Table I (assets/paper/table1.yaml) as data: each
// material's measured period and printed mu_k at 300 K (and 77 K where measured), the spacing
// l +- dl they were measured at, and the literature's range.
#include <pybind11/stl.h>

#include <string>

#include "core/paper_table.hpp"
#include "lab/request/table_request.hpp"
#include "python/arguments.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"
#include "python/lab_data.hpp"

namespace fl::python {

void bind_paper_table(py::module_& m) {
  py::class_<PaperMeasurement>(m, "PaperMeasurement", "One row of Table I (SI).")
      .def_readonly("temperature", &PaperMeasurement::temperature, "K")
      .def_readonly("period", &PaperMeasurement::period, "T +- dT [s], as printed")
      .def_readonly("mu_k", &PaperMeasurement::mu_k, "mu_k +- d mu_k, as printed");
  py::class_<LiteratureRange>(m, "LiteratureRange", "mu_k's range in the literature.")
      .def_readonly("low", &LiteratureRange::low)
      .def_readonly("high", &LiteratureRange::high);
  py::class_<PaperMaterial>(m, "PaperMaterial", "A material of Table I.")
      .def_readonly("key", &PaperMaterial::key, "\"lego\", \"polished-wood\", ...")
      .def_readonly("name", &PaperMaterial::name, "\"LEGO blocks\", ...")
      .def_readonly("note", &PaperMaterial::note)
      .def_readonly("room", &PaperMaterial::room, "at 300 K")
      .def_readonly("cold", &PaperMaterial::cold, "at 77 K, or None")
      .def_readonly("literature", &PaperMaterial::literature, "or None")
      .def_property_readonly(
          "measurements",
          [](const PaperMaterial& p) {
            py::list out;
            out.append(p.room);
            if (p.cold) out.append(*p.cold);
            return out;
          },
          "[room] or [room, cold]");
  py::class_<PaperTable>(m, "PaperTable", R"(The paper's Table I.

for material in table.materials: for row in material.measurements: row.period.value, ...)")
      .def_readonly("source", &PaperTable::source)
      .def_readonly("spacing", &PaperTable::spacing, "l +- dl [m] of the measurements")
      .def_readonly("materials", &PaperTable::materials)
      .def(
          "find",
          [](const PaperTable& t, const std::string& key) -> std::optional<PaperMaterial> {
            const PaperMaterial* p = t.find(key);
            return p ? std::optional(*p) : std::nullopt;
          },
          py::arg("key"), "The material with this key, or None");
  m.def(
      "paper_table",
      [](const std::optional<Path>& assets) { return paper_table_in(asset_dir(assets)); },
      py::kw_only(), py::arg("assets") = py::none(),
      "The paper's Table I, as `frictionlab table` reads it (assets/paper/table1.yaml).");
  const TableRequest defaults;
  m.def(
      "table",
      [](const Quantity& gravity, const Quantity& h_c, const std::optional<Path>& assets) {
        TableRequest r;
        r.gravity = gravity;
        r.h_c = h_c;
        if (assets) r.assets = assets->string();
        return python_value(paper_table_recomputed(r).json());
      },
      py::kw_only(), py::arg("gravity") = defaults.gravity, py::arg("h_c") = defaults.h_c,
      py::arg("assets") = py::none(),
      "The paper's Table I with mu_k recomputed from each period (thin formula at g, thick at "
      "h_c), as `frictionlab table --json` prints it.");
}

}  // namespace fl::python

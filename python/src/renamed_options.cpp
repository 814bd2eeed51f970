// The renamed options of the Python functions, read from the config schemas (renamed_options.hpp),
// and _lrchain.renamed_options(table) for the keyword checks of the Python layer (_keywords.py).
#include "renamed_options.hpp"

#include <stdexcept>
#include <string>
#include <tuple>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "lrchain/jobs/sweep/study_jobs.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
// The renamed list of the table `name` of `schema`.
const std::vector<config::RenamedKey>& renamed_of(const config::TableSchema& schema, const std::string& name) {
  const config::KeySchema* key = schema.find(name);
  if (key == nullptr || !key->table) throw std::logic_error("the config schema has no table [" + name + "]");
  return key->table->renamed;
}
}  // namespace

const std::vector<config::RenamedKey>& renamed_options(std::string_view table) {
  if (table == "bright" || table == "drive" || table == "modulated")
    return renamed_of(jobs::experiment_schema(table), std::string(table));
  if (table == "model bright") return renamed_of(jobs::model_experiment_schema("bright"), "bright");
  if (table == "dark") return renamed_of(jobs::sweep::study_schema("dark continue"), "dark");
  throw std::invalid_argument("renamed_options: no table \"" + std::string(table) +
                              "\" (bright, drive, modulated, model bright, dark)");
}

void register_renamed_options(py::module_& m) {
  m.def(
      "renamed_options",
      [](const std::string& table) {
        std::vector<std::tuple<std::string, std::string, std::string>> out;
        for (const auto& r : renamed_options(table)) out.emplace_back(r.old_name, r.new_name, r.replacement());
        return out;
      },
      py::arg("table"),
      "The renamed options of a config table as (old name, new name, replacement text) tuples, the "
      "replacement text being \"'sites', <note>\" when the meaning changed too.");
}

}  // namespace lrchain::python

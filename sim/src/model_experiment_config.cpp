// Bright-breather configs of any model file (model_experiment_config.hpp).
#include "lrchain/sim/model_experiment_config.hpp"

#include "toml_reading.hpp"

namespace lrchain::sim {

namespace {

using namespace lrchain::config;

// [bright] of a model config: the options of ModelBrightConfig.
std::shared_ptr<const TableSchema> model_bright_table() {
  const ModelBrightConfig d;
  const auto positive = NumberRange::positive();
  return std::make_shared<const TableSchema>(TableSchema{
      "a bright breather of the model started from its NLS ansatz",
      {string("branch", "", "branch name of the model (acoustic, optical, branch0, ...)").require(),
       number("theta", NumberRange::between(0, 3.141592653589793, true, false), "", "carrier wavenumber theta in (0, pi]")
           .require(),
       number("detuning", NumberRange::any(), "sign(h_tilde) 1e-4", "omega_b - omega"),
       number("n0", NumberRange::any(), number_text(d.n0), "initial centre (site), in [-N, N]"),
       integer("N", 10, 50'000'000, std::to_string(d.N), "sites n = -N..N"),
       number("periods", positive, number_text(d.periods), "run length in breather periods T_b"),
       number("sample_every", positive, number_text(d.sample_every), "E, energy and centre sampled every this many T_b"),
       number("dt", positive, "2 pi / (24 omega_max)", "srkn11b step (omega_max: the fastest linear mode)"),
       boolean("ansatz_ends", d.ansatz_ends ? "true" : "false",
               "the sites beyond both ends follow the ansatz (emitting ends; integrated with rkf78)")},
      std::nullopt});
}

}  // namespace

bool is_model_experiment(const Document& doc) {
  const toml::node* model = doc.root().get("model");
  return model != nullptr && model->is_string();
}

const TableSchema& model_experiment_schema() {
  static const TableSchema schema{
      "a bright-breather run of a model file",
      {choice("experiment", {"bright"}, "", "which experiment this file describes").require(),
       string("name", "the file name without .toml", "a label for the run, copied to the JSON summary"),
       string("model", "", "the model file, e.g. \"models/klein_gordon.toml\"").require(),
       table("parameters", std::make_shared<const TableSchema>(TableSchema{
                               "values of the model's parameters (the model file's defaults otherwise)",
                               {},
                               number("", NumberRange::any(), "the model's default", "a parameter of the model")})),
       table("bright", model_bright_table()).require(),
       table("output", config::output_schema())},
      std::nullopt};
  return schema;
}

ModelExperimentConfig load_model_experiment_config(const Document& doc) {
  const CheckedTable root = check(doc, model_experiment_schema());
  ModelExperimentConfig c;
  c.name = config::config_name(root);
  root.read("model", c.model_file);
  if (auto p = root.table("parameters"))
    for (const auto& key : p->keys()) c.parameters.emplace_back(key, *p->number(key));
  const CheckedTable bright = *root.table("bright");
  bright.read("branch", c.branch);
  bright.read("theta", c.bright.theta);
  double d = 0;
  if (bright.read("detuning", d)) c.bright.detuning = d;
  bright.read("n0", c.bright.n0);
  bright.read("N", c.bright.N);
  bright.read("periods", c.bright.periods);
  bright.read("sample_every", c.bright.sample_every);
  bright.read("dt", c.bright.dt);
  bright.read("ansatz_ends", c.bright.ansatz_ends);
  if (auto o = root.table("output")) o->read("dir", c.out_dir);
  return c;
}

}  // namespace lrchain::sim

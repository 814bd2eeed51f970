// Bright-breather and ring configs of any model file (model_experiment_config.hpp).
#include "lrchain/jobs/model_experiment_config.hpp"

#include "located_validation.hpp"
#include "lrchain/sim/bright_run.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "toml_reading.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;  // the numerics this job layer runs

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
       number("n0", NumberRange::any(), number_text(d.n0), "initial centre (site), in [-N, N] with sites = 2N + 1"),
       integer("sites", model_bright_sites.least, model_bright_sites.most, std::to_string(strain_site_count(d.N)),
               "odd number of lattice sites 2N + 1, n = -N..N (strains, or displacements of on-site models)"),
       number("periods", positive, number_text(d.periods), "run length in breather periods T_b"),
       number("sample_every", positive, number_text(d.sample_every), "E, energy and centre sampled every this many T_b"),
       number("dt", positive, "2 pi / (24 omega_max)", "srkn11b step (omega_max: the fastest linear mode)"),
       boolean("ansatz_ends", d.ansatz_ends ? "true" : "false",
               "the sites beyond both ends follow the ansatz (emitting ends; integrated with rkf78)")},
      std::nullopt,
      {{"N", "sites", half_width_renamed_note}}});
}

// [ring] of a model config: the options of RingRunConfig (the ranges of sim::validate).
std::shared_ptr<const TableSchema> model_ring_table() {
  const RingRunConfig d;
  return std::make_shared<const TableSchema>(TableSchema{
      "plane waves of the model on a periodic ring against omega + h U^2/4, and a small packet's speed against c",
      {string("branch", "", "branch name of the model (acoustic, optical, branch0, ...)").require(),
       number("theta", NumberRange::between(0, 3.141592653589793, true, false), "",
              "carrier wavenumber 2 pi k / N in (0, pi]")
           .require(),
       numbers("amplitudes", NumberRange::between(0, 10, true, false), "[0.02, 0.01]",
               "plane-wave amplitudes U of the first field (1 to 64)"),
       integer("sites", 8, 1'000'000, "the smallest N >= 8 with theta N / (2 pi) whole", "ring size N"),
       number("periods", NumberRange::between(10, 1e5, false, false), number_text(d.periods),
              "carrier periods per frequency measurement"),
       number("steps_per_period", NumberRange::between(8, 1e4, false, false), number_text(d.steps_per_period),
              "srkn11b steps per carrier period"),
       number("packet_amplitude", NumberRange::between(0, 10, true, false), "a tenth of the smallest amplitude",
              "wave-packet amplitude"),
       number("packet_width", NumberRange::between(4, 1000, false, false), number_text(d.packet_width),
              "Gaussian width of the packet in sites")},
      std::nullopt});
}

// The schema of a model config whose job table is `job` ([bright] or [ring]).
TableSchema model_schema(const std::string& job, std::shared_ptr<const TableSchema> job_table) {
  return TableSchema{
      "a " + job + " run of a model file",
      {choice("experiment", {"bright", "ring"}, "", "which experiment this file describes").require(),
       string("name", "the file name without .toml", "a label for the run, copied to the JSON summary"),
       string("model", "", "the model file, e.g. \"models/klein_gordon.toml\"").require(),
       table("parameters", std::make_shared<const TableSchema>(TableSchema{
                               "values of the model's parameters (the model file's defaults otherwise)",
                               {},
                               number("", NumberRange::any(), "the model's default", "a parameter of the model")})),
       table(job, std::move(job_table)).require(),
       table("output", config::output_schema())},
      std::nullopt};
}

void read_bright(const CheckedTable& bright, ModelExperimentConfig& c) {
  bright.read("branch", c.branch);
  bright.read("theta", c.bright.theta);
  double d = 0;
  if (bright.read("detuning", d)) c.bright.detuning = d;
  bright.read("n0", c.bright.n0);
  std::int64_t sites = 0;
  if (bright.read("sites", sites))
    config::validate_located(bright, [&] { c.bright.N = strain_half_width(sites, model_bright_sites); });
  bright.read("periods", c.bright.periods);
  bright.read("sample_every", c.bright.sample_every);
  bright.read("dt", c.bright.dt);
  bright.read("ansatz_ends", c.bright.ansatz_ends);
  // The run's own checks (n0 within the lattice, ...) at the line of the key they refuse.
  config::validate_located(bright, [&] { validate(c.bright); });
}

void read_ring(const CheckedTable& ring, ModelExperimentConfig& c) {
  ring.read("branch", c.branch);
  ring.read("theta", c.ring.theta);
  ring.read("amplitudes", c.ring.amplitudes);
  std::int64_t sites = 0;
  if (ring.read("sites", sites)) c.ring.sites = Index(sites);
  ring.read("periods", c.ring.periods);
  ring.read("steps_per_period", c.ring.steps_per_period);
  if (const auto a = ring.number("packet_amplitude")) c.ring.packet_amplitude = *a;
  ring.read("packet_width", c.ring.packet_width);
}

}  // namespace

bool is_model_experiment(const Document& doc) {
  const toml::node* model = doc.root().get("model");
  return model != nullptr && model->is_string();
}

const TableSchema& model_experiment_schema(const std::string& experiment) {
  static const TableSchema bright = model_schema("bright", model_bright_table());
  static const TableSchema ring = model_schema("ring", model_ring_table());
  return experiment == "ring" ? ring : bright;
}

ModelExperimentConfig load_model_experiment_config(const Document& doc) {
  // The experiment key picks the schema; any other value is refused by the check, which lists both.
  const toml::node* kind = doc.root().get("experiment");
  const std::string experiment = kind != nullptr && kind->value<std::string>() == "ring" ? "ring" : "bright";
  const CheckedTable root = check(doc, model_experiment_schema(experiment));
  ModelExperimentConfig c;
  root.read("experiment", c.experiment);
  c.name = config::config_name(root);
  root.read("model", c.model_file);
  if (auto p = root.table("parameters"))
    for (const auto& key : p->keys()) c.parameters.emplace_back(key, *p->number(key));
  if (c.experiment == "ring")
    read_ring(*root.table("ring"), c);
  else
    read_bright(*root.table("bright"), c);
  if (auto o = root.table("output")) o->read("dir", c.out_dir);
  return c;
}

}  // namespace lrchain::jobs

// The corpus's hand-written data (corpus_tables.hpp): bases, valid-range exceptions, file options.
#include "corpus_tables.hpp"

namespace lrchain::corpus {

const char* label(BadValue v) {
  switch (v) {
    case BadValue::nan: return "nan";
    case BadValue::inf: return "inf";
    case BadValue::minus_inf: return "-inf";
    case BadValue::minus_one: return "-1";
    case BadValue::zero: return "0";
    case BadValue::huge: return "1e308";
    case BadValue::huge_pi: return "1e300pi";
    case BadValue::empty: return "empty";
    case BadValue::word: return "word";
    case BadValue::wrong_type: return "wrong-type";
  }
  return "?";
}

const std::map<std::string, std::vector<std::string>>& base_commands() {
  static const std::map<std::string, std::vector<std::string>> bases = {
      {"coeffs", {"--theta", "pi/2", "--branch", "optical", "--json"}},
      {"regime intervals", {"--samples", "64"}},
      {"regime map", {"--out", "@OUT@", "--nx", "8", "--ny", "8", "--no-curves", "--no-figures"}},
      {"regime thresholds", {"--scan", "10"}},
      {"simulate bright",
       {"--branch", "optical", "--theta", "pi/2", "--sites", "101", "--periods", "1", "--sample-every", "0.25",
        "--spacetime-every", "0.5", "--snapshots", "0", "1", "--out", "@OUT@", "--json"}},
      {"simulate ring",
       {"--model", LRCHAIN_SOURCE_DIR "/models/fput.toml", "--branch", "acoustic", "--theta", "pi/2", "--periods",
        "10", "--packet-width", "4", "--out", "@OUT@", "--json"}},
      {"simulate drive",
       {"--sites", "50", "--t-end", "2", "--switch-off-time", "1", "--sample-every", "1", "--spacetime-every", "2",
        "--snapshots", "1", "2", "--front-fit-start", "0", "--front-fit-end", "2", "--out", "@OUT@", "--json"}},
      {"simulate modulated",
       {"--sites", "21", "--theta-waves", "13", "--t-end", "2", "--sample-every", "1", "--snapshots", "0", "1",
        "--speed-fit-start", "0", "--speed-fit-end", "2", "--checkpoint-every", "1", "--out", "@OUT@", "--json"}},
      {"dark solve", {"--omega-b", "2.42", "--sites", "21", "--quiet", "--out", "@OUT@"}},
      {"dark floquet", {"--omega-b", "2.42", "--sites", "21", "--quiet", "--out", "@OUT@"}},
      {"dark continue", {"--omega-b", "2.42", "--sites", "21", "--points", "2", "--quiet", "--out", "@OUT@"}},
      {"dark evolve", {"--omega-b", "2.42", "--sites", "21", "--t-end", "3", "--quiet", "--out", "@OUT@"}},
      {"bright solve", {"--model", "klein_gordon", "--omega-b", "1.3", "--sites", "21", "--quiet", "--out", "@OUT@"}},
      {"bright floquet", {"--model", "klein_gordon", "--omega-b", "1.3", "--sites", "21", "--quiet", "--out", "@OUT@"}},
      {"bright continue",
       {"--model", "klein_gordon", "--omega-b", "1.3", "--sites", "21", "--points", "2", "--quiet", "--out", "@OUT@"}},
      {"bright evolve",
       {"--model", "klein_gordon", "--omega-b", "1.3", "--sites", "21", "--periods", "2", "--quiet", "--out", "@OUT@"}},
      {"wave solve", {"--model", "fput", "--branch", "acoustic", "--theta", "2.5", "--amplitude", "0.02", "--out", "@OUT@"}},
      {"wave continue",
       {"--model", "fput", "--branch", "acoustic", "--theta", "2.5", "--amplitudes", "0.01", "0.02", "--out", "@OUT@"}},
      {"wave stability",
       {"--model", "fput", "--branch", "acoustic", "--theta", "2.5", "--amplitude", "0.02", "--k-points", "20", "--out",
        "@OUT@"}},
      {"wave fate",
       {"--model", "fput", "--theta", "2.5", "--amplitude", "0.02", "--k-points", "10", "--ring-sites", "16", "--periods",
        "10", "--out", "@OUT@"}},
      {"wave standing",
       {"--model", "fput", "--theta", "2*pi/5", "--amplitude", "0.05", "--ring-sites", "10", "--out", "@OUT@"}},
      {"reproduce", {"--only", "coefficients", "--jobs", "1", "--out", "@OUT@"}},
      {"sweep",
       {"--config", LRCHAIN_SOURCE_DIR "/tests/corpus/sweep_small.toml", "--output", "@TMP@/sweep.h5", "--threads", "1",
        "--quiet"}},
  };
  return bases;
}

const std::map<std::string, std::vector<std::string>>& option_context() {
  static const std::map<std::string, std::vector<std::string>> context = {
      {"delta0-range", {"--plane", "delta0-omega"}},
      {"omega-range", {"--plane", "delta0-omega"}},
      {"axis-range", {"--model", LRCHAIN_SOURCE_DIR "/models/fput.toml", "--axis", "b"}},  // a model's axis
  };
  return context;
}

const std::map<std::string, std::string>& pair_partner() {
  static const std::map<std::string, std::string> partner = {
      {"rho-range", "0.1"}, {"delta0-range", "0.01"}, {"omega-range", "0.5"}, {"axis-range", "0.1"}};
  return partner;
}

const std::set<std::string>& numeric_text_options() {
  static const std::set<std::string> names = {"rho-range", "delta0-range", "omega-range"};
  return names;
}

const std::set<BadValue>& possibly_valid(const std::string& name) {
  using enum BadValue;
  static const std::map<std::string, std::set<BadValue>> table = {
      {"detuning", {minus_one}},             // any nonzero value with the sign of h_tilde (< 0 at the bases)
      {"n0", {minus_one, zero}},             // the breather centre may be any site
      {"error-window", {minus_one, zero}},   // t <= 0: no error window (the default is -1)
      {"error-window-end", {minus_one, zero}},  // the config key of --error-window
      {"trailing-fit-start", {zero}},        // 0: no trailing-structure fit (the default)
      {"snapshots", {zero}},                 // a snapshot at t = 0 is the initial state
      {"rel-tol", {zero}},                   // pure absolute error control
      {"switch-off-time", {minus_one, zero}},  // chi(t) is defined for any switch-off time t_m
      {"front-fit-start", {minus_one, zero}},  // a fit window opening before the run starts at t = 0
      {"speed-fit-start", {minus_one, zero}},
      {"modulation-depth", {zero}},          // b = 0: no modulation
      {"modulation", {zero}},                // wave fate: b = 0, no modulation (the default)
      {"noise", {zero}},                     // wave fate: no noise (round-off, or --modulation, seeds the growth)
      {"omega-min", {minus_one, zero}},      // lower stop of the continuation (default 0)
      {"omega-max", {minus_one, zero}},      // <= 0 today means "the band edge"
      {"ds", {minus_one}},                   // the sign of the first step may pick the direction
      {"locate-tolerance", {zero}},          // 0: crossings bracketed, not located
      {"name", {huge_pi, word, empty}},      // a run's name is any text
      {"dir", {huge_pi, word, empty}},       // an output directory is any path; empty: none
      {"values", {minus_one, zero, huge}},   // a sweep axis may hold any number: a point outside the
      {"from", {minus_one, zero, huge}},     // job's range is recorded as an invalid point
      {"to", {minus_one, zero, huge}},
      {"checkpoint-seconds", {huge}},        // any positive time between rewrites of the results file
      {"csv-max-points", {zero}},            // 0: no CSV view
      {"axis-range", {huge, huge_pi}},       // fput's b may take any value: [0.1, 1e308] is a valid axis
  };
  static const std::set<BadValue> none;
  const auto it = table.find(name);
  return it == table.end() ? none : it->second;
}

std::string option_for_config_key(const std::string& key) {
  if (key == "snapshot_periods" || key == "snapshot_times") return "snapshots";
  std::string name = key;
  for (char& c : name)
    if (c == '_') c = '-';
  return name;
}

const std::vector<FileOption>& file_options() {
  static const std::vector<FileOption> files = {
      {"simulate", "config", false},
      {"sweep", "config", false},
      {"simulate modulated", "restart", false},
      {"reproduce", "examples", true},
      {"reproduce", "errata", false},
  };
  return files;
}

const std::vector<OutputOption>& output_options() {
  static const std::vector<OutputOption> outputs = {
      {"regime map", "out", false},        {"simulate bright", "out", false}, {"simulate drive", "out", false},
      {"simulate ring", "out", false},
      {"simulate modulated", "out", false}, {"simulate modulated", "checkpoint", true},
      {"dark solve", "out", false},         {"dark floquet", "out", false},    {"dark continue", "out", false},
      {"dark evolve", "out", false},        {"reproduce", "out", false},
      {"bright solve", "out", false},       {"bright floquet", "out", false},  {"bright continue", "out", false},
      {"wave solve", "out", false},         {"wave continue", "out", false},   {"wave stability", "out", false},
      {"wave fate", "out", false},         {"wave standing", "out", false},   {"bright evolve", "out", false},
      {"sweep", "output", true},
  };
  return outputs;
}

const std::vector<std::string>& sweep_config_files() {
  static const std::vector<std::string> files = {"sweep_small.toml", "sweep_range.toml"};
  return files;
}

std::string command_for_experiment(const std::string& kind) { return "simulate " + kind; }

}  // namespace lrchain::corpus

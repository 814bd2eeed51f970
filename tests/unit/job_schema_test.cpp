// The job option schemas (lrchain/jobs/option_schema.hpp) against the config-file schemas that
// docs/configs.md is generated from (experiment_schema: config_strict_test checks the page against
// them): a key that both hold has the same default in both, so the command's help, Python's defaults
// and the page agree. The CLI's and Python's use of the job schemas: tests/python/test_job_schemas.py.
#include <doctest/doctest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/option_schema.hpp"

namespace {

using lrchain::jobs::JobOption;

// The words of a default as either schema writes it: "[0, 50.125, 200]" and "0 50.125 200" both give
// {"0", "50.125", "200"}.
std::vector<std::string> words(std::string text) {
  for (char& ch : text)
    if (ch == '[' || ch == ']' || ch == ',') ch = ' ';
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// Two words of a default equal: numbers as numbers (1e-10 and 1.0e-10), else as text.
bool same_word(const std::string& a, const std::string& b) {
  char* end_a = nullptr;
  char* end_b = nullptr;
  const double x = std::strtod(a.c_str(), &end_a), y = std::strtod(b.c_str(), &end_b);
  return *end_a == '\0' && *end_b == '\0' ? x == y : a == b;
}

// Equal defaults: the same words; or, where the config file's text explains the default ("automatic for
// fixed-step steppers (energy-error probe), 0.05 for adaptive"), the value is one of its words.
bool same_default(const std::string& value, const std::string& config_text) {
  const auto wa = words(value), wb = words(config_text);
  if (wa.size() == wb.size()) {
    bool all = true;
    for (std::size_t i = 0; i < wa.size(); ++i) all = all && same_word(wa[i], wb[i]);
    if (all) return true;
  }
  if (wa.size() != 1) return false;
  for (const auto& w : wb)
    if (same_word(wa[0], w)) return true;
  return false;
}

}  // namespace

TEST_CASE("job schemas: every simulate default agrees with the config file's schema (docs/configs.md)") {
  for (const std::string kind : {"bright", "drive", "modulated"}) {
    const auto& top = lrchain::jobs::experiment_schema(kind);
    const auto* run = top.find(kind);
    const auto* integrator = top.find("integrator");
    REQUIRE(run != nullptr);
    REQUIRE(integrator != nullptr);
    int compared = 0;
    for (const JobOption& o : lrchain::jobs::job_options(kind)) {
      if (o.default_value.is_null()) continue;
      const auto* key = run->table->find(o.key);
      if (key == nullptr || key->name != o.key) key = integrator->table->find(o.key);
      if (key == nullptr || key->name != o.key) continue;  // an option of the command line or Python alone
      if (key->required) continue;  // theta: the file must give it (Python's default pi/2 is its own)
      // The value itself (a default_note such as pi/2 spells it for reading): the JSON default.
      const std::string value = o.default_value.is_string() ? o.default_value.get<std::string>() : o.default_value.dump();
      INFO(kind, " ", o.key, ": job schema ", value, ", config schema ", key->default_text);
      CHECK(same_default(value, key->default_text));
      ++compared;
    }
    // most options are in both (bright 16 of 19; the others are the command's or Python's own)
    CHECK(compared >= 10);
  }
}

TEST_CASE("job schemas: each job lists each key once and names its front-end spellings") {
  for (const std::string& job : lrchain::jobs::job_names()) {
    const auto& options = lrchain::jobs::job_options(job);
    REQUIRE_FALSE(options.empty());
    for (std::size_t i = 0; i < options.size(); ++i) {
      INFO(job, " ", options[i].key);
      CHECK((options[i].cli.empty() || options[i].cli.starts_with("--")));
      CHECK_FALSE(options[i].doc.empty());
      CHECK(options[i].python.find('-') == std::string::npos);
      for (std::size_t j = i + 1; j < options.size(); ++j) CHECK(options[i].key != options[j].key);
    }
  }
}

TEST_CASE("job schemas: a refusal naming a Config key is re-spelled as the command's option") {
  const auto& bright = lrchain::jobs::job_options("bright");
  CHECK(lrchain::jobs::cli_name(bright, "snapshot_periods") == "snapshots");
  CHECK(lrchain::jobs::cli_name(bright, "error_window_end") == "error-window");
  CHECK(lrchain::jobs::cli_name(bright, "trailing_fit_start") == "trailing-fit-start");  // config files only
  const lrchain::InvalidParameter e("t_end", "must be a finite number > 0");
  const auto renamed = lrchain::jobs::renamed_parameter(e, lrchain::jobs::cli_name(bright, "t_end"));
  CHECK(std::string(renamed.what()) == "invalid t-end: must be a finite number > 0");
  CHECK(renamed.parameter() == "t-end");
}

// Job options once (option_schema.hpp): their help and JSON, and the registry of every job's schema.
#include "lrchain/jobs/option_schema.hpp"

#include <fmt/format.h>

#include <map>
#include <stdexcept>

#include "lrchain/jobs/bright_breather_schema.hpp"
#include "lrchain/jobs/coeffs.hpp"
#include "lrchain/jobs/dark_schema.hpp"
#include "lrchain/jobs/regime_schema.hpp"
#include "lrchain/jobs/simulate/simulate_schema.hpp"

namespace lrchain::jobs {

namespace {

// `text` with every "{name}" replaced by `value`.
std::string filled(std::string text, const std::string& name, const std::string& value) {
  const std::string slot = "{" + name + "}";
  for (auto at = text.find(slot); at != std::string::npos; at = text.find(slot, at + value.size()))
    text.replace(at, slot.size(), value);
  return text;
}

std::string value_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return fmt::format("{:g}", v.get<double>());
  if (v.is_array()) {
    std::string s;
    for (const auto& item : v) s += (s.empty() ? "" : " ") + value_text(item);
    return s;
  }
  return v.dump();
}

const std::map<std::string, const std::vector<JobOption>& (*)()>& registry() {
  static const std::map<std::string, const std::vector<JobOption>& (*)()> jobs{
      {"dark", &dark::dark_options},
      {"coeffs", &coeffs_options},
      {"bright", &bright_options},
      {"bright --model", &model_bright_options},
      {"bright breather", &bright_breather::bright_breather_options},
      {"drive", &drive_options},
      {"modulated", &modulated_options},
      {"ring", &ring_options},
      {"regime intervals", &regime_intervals_options},
      {"regime map", &regime_map_options},
      {"regime curves", &regime_curves_options},
      {"regime thresholds", &regime_thresholds_options},
  };
  return jobs;
}

}  // namespace

const std::vector<JobOption>& job_options(const std::string& job) {
  const auto it = registry().find(job);
  if (it == registry().end()) throw std::out_of_range("no job " + job);
  return it->second();
}

std::vector<std::string> job_names() {
  std::vector<std::string> names;
  for (const auto& [name, options] : registry()) names.push_back(name);
  return names;
}

const JobOption& find_option(const std::vector<JobOption>& options, const std::string& key) {
  for (const JobOption& o : options)
    if (o.key == key) return o;
  throw std::out_of_range("no option " + key);
}

std::string default_text(const JobOption& o) {
  return !o.default_note.empty() || o.default_value.is_null() ? o.default_note : value_text(o.default_value);
}

std::string help_text(const JobOption& o) {
  if (!o.help.empty()) return filled(filled(filled(o.help, "doc", o.doc), "range", o.range), "default", default_text(o));
  std::string facts = o.range;
  const std::string value = o.required                                           ? "required"
                            : o.default_value.is_null() && o.default_note.empty() ? "default: none"
                                                                                   : "default " + default_text(o);
  facts += (facts.empty() ? "" : "; ") + value;
  return o.doc + " [" + facts + "]";
}

std::string cli_name(const std::vector<JobOption>& options, const std::string& key) {
  for (const JobOption& o : options)
    if (o.key == key && o.cli.starts_with("--")) return o.cli.substr(2);
  std::string name = key;
  for (char& ch : name)
    if (ch == '_') ch = '-';
  return name;
}

InvalidParameter renamed_parameter(const InvalidParameter& e, const std::string& name) {
  const std::string what = e.what(), prefix = "invalid " + e.parameter() + ": ";
  return InvalidParameter(name, what.starts_with(prefix) ? what.substr(prefix.size()) : what);
}

nlohmann::json to_json(const JobOption& o) {
  return {{"key", o.key},           {"cli", o.cli},         {"python", o.python},         {"steps", o.steps},
          {"default", o.default_value}, {"required", o.required}, {"range", o.range},       {"doc", o.doc},
          {"help", help_text(o)},   {"default_text", default_text(o)}};
}

}  // namespace lrchain::jobs

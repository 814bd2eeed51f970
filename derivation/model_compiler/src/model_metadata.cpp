#include "model_metadata.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace lrchain {

std::string model_metadata_json(const derivation::ModelDerivation& m) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const auto& p : m.file.parameters) {
    const auto& r = p.range;
    parameters.push_back({{"name", p.name},
                          {"default", p.default_value.to_double()},
                          {"range", r.text},
                          {"has_lower", r.has_lower},
                          {"lower", r.has_lower ? r.lower.to_double() : 0.0},
                          {"lower_closed", r.lower_closed},
                          {"has_upper", r.has_upper},
                          {"upper", r.has_upper ? r.upper.to_double() : 0.0},
                          {"upper_closed", r.upper_closed}});
  }
  nlohmann::json intermediates = nlohmann::json::array(), branches = nlohmann::json::array();
  for (const auto& i : m.file.intermediates) intermediates.push_back(i.name);
  for (const auto& b : m.branches) branches.push_back(b.name);
  const nlohmann::json j{{"name", m.file.name},
                         {"description", m.file.description},
                         {"file_hash", m.file.hash},
                         {"file_sha256", m.file.sha256},
                         {"mean_flow", m.coefficients.mean_flow},
                         {"degree", m.branches.size()},
                         {"parameters", parameters},
                         {"intermediates", intermediates},
                         {"branches", branches}};
  return j.dump();  // ensure_ascii off: the text is embedded through c_string_literal, which escapes any byte
}

ModelDefinition parse_model_metadata(std::string_view text, const std::string& library) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    ModelDefinition d;
    d.name = j.at("name").get<std::string>();
    d.description = j.at("description").get<std::string>();
    d.file_hash = j.at("file_hash").get<std::uint64_t>();
    d.file_sha256 = j.at("file_sha256").get<std::string>();
    d.mean_flow = j.at("mean_flow").get<bool>();
    d.degree = j.at("degree").get<Index>();
    for (const auto& p : j.at("parameters")) {
      ModelParameter q;
      q.name = p.at("name").get<std::string>();
      q.default_value = p.at("default").get<double>();
      q.range_text = p.at("range").get<std::string>();
      q.has_lower = p.at("has_lower").get<bool>();
      q.lower = p.at("lower").get<double>();
      q.lower_closed = p.at("lower_closed").get<bool>();
      q.has_upper = p.at("has_upper").get<bool>();
      q.upper = p.at("upper").get<double>();
      q.upper_closed = p.at("upper_closed").get<bool>();
      d.parameters.push_back(q);
    }
    for (const auto& i : j.at("intermediates")) d.intermediates.push_back(i.get<std::string>());
    for (const auto& b : j.at("branches")) d.branch_names.push_back(b.get<std::string>());
    if (d.name.empty() || d.branch_names.empty() || d.degree != Index(d.branch_names.size()))
      throw std::runtime_error("an incomplete description");
    return d;
  } catch (const std::exception& e) {
    throw std::runtime_error(library + ": not a model description lrchain wrote (" + e.what() + ")");
  }
}

}  // namespace lrchain

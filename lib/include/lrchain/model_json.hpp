#pragma once
// The "model" object every JSON output of lrchain echoes (CLI summaries, summary.json, HDF5
// attributes, Python results): {"name", "file_hash", "parameters": {name: value, ...}}.
// Header-only so that the core library does not depend on nlohmann-json.
#include <nlohmann/json.hpp>

#include "lrchain/model.hpp"

namespace lrchain {

// {"name", "file_hash" ("0x" + 16 hex digits), "parameters": {name: value}} (keys sorted by name).
inline nlohmann::json model_json(const Model& model) {
  nlohmann::json parameters = nlohmann::json::object();
  const auto& d = model.definition();
  for (std::size_t i = 0; i < d.parameters.size(); ++i) parameters[d.parameters[i].name] = model.inputs()[i];
  return {{"name", d.name}, {"file_hash", model_hash_text(d.file_hash)}, {"parameters", parameters}};
}

}  // namespace lrchain

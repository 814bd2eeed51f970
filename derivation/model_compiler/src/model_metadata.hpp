#pragma once
// What a compiled model object says about its model (name, parameters and ranges, branches, ...):
// one JSON document, embedded in the object as a C string literal (c_string_literal), so no text of
// the model file can add, remove or change a record.
#include <string>
#include <string_view>

#include "lrchain/derivation/model_derivation.hpp"
#include "lrchain/model.hpp"

namespace lrchain {

// The JSON text of the definition of `m` (everything ModelDefinition holds but the evaluators).
std::string model_metadata_json(const derivation::ModelDerivation& m);

// The definition (evaluators left empty) of a JSON text of model_metadata_json; std::runtime_error
// naming `library` when it is not one.
ModelDefinition parse_model_metadata(std::string_view text, const std::string& library);

}  // namespace lrchain

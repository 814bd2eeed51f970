// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive: the shipped models (models/*.toml) with their emitted evaluators.
#pragma once

#include <vector>

#include "lrchain/generated/model_diatomic_chain.hpp"
#include "lrchain/generated/model_fput.hpp"
#include "lrchain/generated/model_homogeneous_chain.hpp"
#include "lrchain/generated/model_klein_gordon.hpp"
#include "lrchain/generated/model_newtons_cradle.hpp"
#include "lrchain/generated/model_resonant_chain.hpp"
#include "lrchain/generated/model_resonant_chain_polynomial.hpp"

namespace lrchain::generated {

// Definitions of every shipped model, sorted by name.
inline std::vector<lrchain::ModelDefinition> shipped_model_definitions() {
  std::vector<lrchain::ModelDefinition> models;
  models.push_back(model_diatomic_chain::definition());
  models.push_back(model_fput::definition());
  models.push_back(model_homogeneous_chain::definition());
  models.push_back(model_klein_gordon::definition());
  models.push_back(model_newtons_cradle::definition());
  models.push_back(model_resonant_chain::definition());
  models.push_back(model_resonant_chain_polynomial::definition());
  return models;
}

}  // namespace lrchain::generated

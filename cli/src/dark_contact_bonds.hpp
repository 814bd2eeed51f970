#pragma once
// The one-sided contacts of a model file (a [functions] entry with `contact`) as overlaps in the
// dark solver's lattice variables, so that its contact changes are located (docs/dark-models.md).
#include <string>

#include "lrchain/model.hpp"
#include "lrchain/sim/dark/contact_bonds.hpp"

namespace lrchain::cli {

// One bond per distinct call F(argument) of a one-sided law (up to a site shift), with the overlap
// s_n = contact(argument at site n) at `model`'s parameter values; strain form (r, w_f) when
// `strain_form`, else displacements. Throws InputError when an argument is not linear in the fields.
sim::dark::ContactBonds model_contact_bonds(const std::string& file, const Model& model, bool strain_form);

}  // namespace lrchain::cli

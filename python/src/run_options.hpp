#pragma once
// Options of a run given from Python as a dict {field name: value}: each known key is assigned to its
// field of the C++ config, a renamed key is a TypeError naming its new name, another unknown key a
// TypeError naming the allowed ones.
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <pybind11/pybind11.h>

#include "lrchain/config/renamed_key.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/integrator.hpp"

namespace lrchain::python {

using OptionTarget = std::variant<double*, std::optional<double>*, long*, std::size_t*, bool*, std::string*, std::vector<double>*,
                                  Params*, Branch*, sim::StepperKind*>;

// Assigns options[key] to *targets.at(key) for every key of options.
void assign_options(const pybind11::dict& options, const std::map<std::string, OptionTarget>& targets,
                    const char* function, const std::vector<config::RenamedKey>& renamed = {});

}  // namespace lrchain::python

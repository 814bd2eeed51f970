#pragma once
// Parameter values of a model file: exact numbers from TOML values and intervals such as "(0, inf)".
#include <ginac/ginac.h>
#include <toml++/toml.h>

#include <string>

#include "lrchain/derivation/model_file.hpp"

namespace lrchain::derivation {

// A number: TOML integer, float (read through its shortest decimal text) or a string "4/9".
bool exact_value(const toml::node& node, GiNaC::numeric& value);

// "(0, inf)", "[1, 4]", "[0, inf)": open/closed bounds, numbers or fractions, +-inf; InputError
// prefixed with `where` otherwise.
ParameterRange parse_range(const std::string& text, const std::string& where);

}  // namespace lrchain::derivation

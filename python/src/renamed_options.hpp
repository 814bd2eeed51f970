#pragma once
// The renamed keyword arguments of the Python functions: the renamed keys of the config table that
// has the same options (the schema's RenamedKey list, one list for config files, sweeps and Python).
#include <string_view>
#include <vector>

#include "lrchain/config/renamed_key.hpp"

namespace lrchain::python {

// The renamed keys of `table`: "bright", "drive", "modulated" (the simulate configs' tables),
// "model bright" (a model file's [bright]) or "dark" (the [dark] table of a dark-continue sweep
// base, the options of `lrchain dark ...`). std::invalid_argument for another name.
const std::vector<config::RenamedKey>& renamed_options(std::string_view table);

}  // namespace lrchain::python

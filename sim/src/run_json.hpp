#pragma once
// Forwarding header, kept while sim/src/dark/dark_hdf5.cpp includes it for model_json (the run
// summaries' JSON moved to the job layer, jobs/src/simulate/run_json.hpp): include
// lrchain/model_json.hpp there and delete this file.
#include <nlohmann/json.hpp>

#include "lrchain/model_json.hpp"

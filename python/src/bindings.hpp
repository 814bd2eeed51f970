#pragma once
// The parts of the compiled module _lrchain, each registered by its own file.
#include <pybind11/pybind11.h>

namespace lrchain::python {

void register_errors(pybind11::module_& m);        // errors.cpp: C++ exceptions -> Python
void register_params(pybind11::module_& m);        // params_binding.cpp: Params
void register_coefficients(pybind11::module_& m);  // coefficients_binding.cpp: batch NLS coefficients
void register_model(pybind11::module_& m);         // model_binding.cpp: load_model, Model
void register_regime(pybind11::module_& m);        // regime_binding.cpp: intervals, maps, curves
void register_simulate(pybind11::module_& m);      // simulate_binding.cpp: bright, drive, modulated
void register_dark(pybind11::module_& m);          // dark_binding.cpp: exact dark breathers
void register_model_simulate(pybind11::module_& m);  // model_simulate_binding.cpp: model bright, ring
void register_model_dark(pybind11::module_& m);      // model_dark_binding.cpp: model dark breathers
void register_bright_breather(pybind11::module_& m);  // bright_breather_binding.cpp: exact bright breathers
void register_renamed_options(pybind11::module_& m);  // renamed_options.cpp: renamed keyword arguments
void register_option_caps(pybind11::module_& m);      // option_caps_binding.cpp: caps shared with the CLI
void register_real_numbers(pybind11::module_& m);     // real_numbers.cpp: complex numbers refused
void register_build_info(pybind11::module_& m);       // build_info_binding.cpp: __version__, provenance()
void register_sweep(pybind11::module_& m);            // sweep_binding.cpp: lrchain.sweep

}  // namespace lrchain::python

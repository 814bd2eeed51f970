// The compiled module lrchain._lrchain; the package lrchain (python/lrchain) wraps it.
#include "bindings.hpp"

PYBIND11_MODULE(_lrchain, m) {
  m.doc() = "Compiled part of lrchain (pybind11); use the package lrchain.";
  lrchain::python::register_errors(m);
  lrchain::python::register_params(m);
  lrchain::python::register_coefficients(m);
  lrchain::python::register_model(m);
  lrchain::python::register_regime(m);
  lrchain::python::register_simulate(m);
  lrchain::python::register_dark(m);
  lrchain::python::register_model_simulate(m);
  lrchain::python::register_model_dark(m);
  lrchain::python::register_bright_breather(m);
  lrchain::python::register_renamed_options(m);
  lrchain::python::register_option_caps(m);
  lrchain::python::register_real_numbers(m);
  lrchain::python::register_build_info(m);
  lrchain::python::register_sweep(m);
}

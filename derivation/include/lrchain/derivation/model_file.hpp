#pragma once
// A lattice model read from a TOML file (docs/models.md): parameters with defaults and ranges,
// named force laws F(r) replaced by their cubic Taylor polynomials about equilibrium, fields with
// masses and force expressions in shifted fields u[n+m] (|m| <= 3), turned into a LatticeDescription.
#include <ginac/ginac.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/derivation/model.hpp"

namespace lrchain::derivation {

// An interval such as "(0, inf)" or "[1, 4]"; missing bounds are infinite.
struct ParameterRange {
  std::string text;
  bool has_lower = false, has_upper = false, lower_closed = false, upper_closed = false;
  GiNaC::numeric lower, upper;
  bool contains(const GiNaC::numeric& value) const;
};

struct ModelParameter {
  std::string name, description;
  GiNaC::realsymbol symbol;
  GiNaC::numeric default_value;  // exact (a fraction "4/9" stays 4/9)
  ParameterRange range;
  int line = 0;
};

// A named force law F(argument) = expression; optionally one-sided (zero where `contact` < 0).
struct ModelFunction {
  std::string name, argument, expression_text, contact_text;
  GiNaC::realsymbol argument_symbol;
  GiNaC::ex expression, contact;   // contact: ex() when the law is not one-sided
  std::vector<std::string> taylor_names;  // names of F'(r0), F''(r0)/2, F'''(r0)/6, or empty
};

// A named Taylor coefficient of a force law (e.g. K2 = alpha delta0^(alpha-1)), kept as a symbol.
struct NamedIntermediate {
  std::string name;
  GiNaC::realsymbol symbol;
  GiNaC::ex value;  // in the parameters
};

// An expression of the file that the derivation evaluates at the parameter values (a function's
// expression) or divides by (a field's mass, the linear stiffness F'(r0) of a named law at its
// equilibrium), with where it is written: blamed when the derivation fails at the parameter values.
struct DivisorTerm {
  std::string where;     // "file:line: force of field u" / "file:line: mass of field u"
  std::string what;      // "F'(r0) of function F" / "the mass"
  GiNaC::ex value;       // in the parameters (and a function's argument)
  bool divisor = true;   // false: only its value must exist (a function's expression)
};

struct ModelFile {
  std::string path, name, description;
  std::uint64_t hash = 0;  // FNV-1a 64 of the file's bytes (displayed)
  std::string sha256;      // SHA-256 (hex) of the file's bytes (its identity)
  std::vector<ModelParameter> parameters;
  std::vector<ModelFunction> functions;
  std::vector<NamedIntermediate> intermediates;
  std::vector<std::string> mass_text, force_text;  // as written, one per field
  std::vector<DivisorTerm> divisors;               // masses and linear stiffnesses, in file order
  std::string first_force_where;                   // "file:line: force of field u" of the first field
  LatticeDescription model;                              // what the engine derives
};

// Reads and checks a model file; throws lrchain::InputError naming file:line and the problem.
ModelFile load_model_file(const std::filesystem::path& path);

// The same from text (`path` is used in messages only).
ModelFile parse_model_text(const std::string& text, const std::string& path);

// Parameter values: defaults overridden by `overrides` (name, number or fraction text), each checked
// against its range (lrchain::InvalidParameter), plus the named intermediates evaluated at them.
GiNaC::exmap parameter_values(const ModelFile& model, const std::vector<std::pair<std::string, std::string>>& overrides);

// "0x" + 16 hex digits.
std::string hash_text(std::uint64_t hash);

}  // namespace lrchain::derivation

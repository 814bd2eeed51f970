#include "lrchain/derivation/model_derivation.hpp"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "lrchain/derivation/derivation_stop.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

bool ModelDerivation::passed() const {
  for (const auto& c : checks)
    if (!c.passed) return false;
  return true;
}

namespace {

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

// The sentence for a failure of the symbolic engine while deriving `file` at `values`: the first
// mass or linear stiffness that is zero or undefined there, else the first force, named file:line.
std::string blame(const ModelFile& file, const exmap& values, const std::string& what) {
  for (const auto& d : file.divisors) {
    try {
      const ex v = evalf(d.value.subs(values, subs_options::no_pattern));
      if (d.divisor && v.is_zero())
        return d.where + ": " + d.what + " is zero at these parameter values, so model " + file.name +
               " has no linear waves to expand about (" + first_line(what) + ")";
    } catch (const std::exception& e) {
      return d.where + ": " + d.what + " cannot be evaluated at these parameter values (" + first_line(e.what()) + ")";
    }
  }
  return (file.first_force_where.empty() ? file.path : file.first_force_where) + ": model " + file.name +
         " cannot be derived at these parameter values (" + first_line(what) + ")";
}

std::unique_ptr<ModelDerivation> derive_checked(ModelFile file, const exmap& values, const Symbols& s);

}  // namespace

// Failures of GiNaC/CLN inside (a division by zero, a pole, an overflow) are the file's: InputError.
std::unique_ptr<ModelDerivation> derive_model(ModelFile file, const exmap& values, const Symbols& s) {
  const ModelFile copy = file;
  try {
    return derive_checked(std::move(file), values, s);
  } catch (const InputError&) {
    throw;
  } catch (const DerivationStopped&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(blame(copy, values, e.what()));
  }
}

namespace {

std::unique_ptr<ModelDerivation> derive_checked(ModelFile file, const exmap& values, const Symbols& s) {
  auto m = std::make_unique<ModelDerivation>();
  m->file = std::move(file);
  m->values = values;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    m->coefficients = derive(m->file.model, s);
  } catch (const DerivationStopped&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(m->file.path + ": model " + m->file.name + " cannot be derived: " + e.what());
  }
  const auto t1 = std::chrono::steady_clock::now();
  m->branches = find_branches(m->coefficients, s, m->values);
  bool any_real = false;
  for (const auto& b : m->branches) any_real |= b.real;
  if (!any_real)
    throw InputError(m->file.path + ": model " + m->file.name + " has no real branch at these parameter values (" +
                     m->branches.front().name + ": " + m->branches.front().problem + ")");
  m->checks = run_model_checks(*m, s);
  const auto t2 = std::chrono::steady_clock::now();
  m->derive_seconds = std::chrono::duration<double>(t1 - t0).count();
  m->check_seconds = std::chrono::duration<double>(t2 - t1).count();
  return m;
}

}  // namespace

std::vector<std::pair<std::string, ex>> symbolic_coefficients(const ModelDerivation& m, const Symbols& s) {
  const DerivedCoefficients& d = m.coefficients;
  const realsymbol n1("nonresonance1"), n2("nonresonance2"), beta("beta"), h("h"), lambda("lambda");
  std::vector<std::pair<std::string, ex>> out{
      {"dispersion", d.dispersion},
      {"group_velocity", d.group_velocity},
      {"gamma", d.gamma},
      {"curvature", s.gamma * d.curvature_over_gamma},
      {"nonresonance1", d.nonresonance1},
      {"h", s.gamma * d.h_n1_over_gamma / n1},
  };
  if (d.mean_flow) {
    out.insert(out.begin() + 4, {"beta", s.gamma * d.beta_over_gamma});
    out.push_back({"nonresonance2", d.nonresonance2});
    out.push_back({"lambda", d.lambda_n2 / n2});
    out.push_back({"h_tilde", h - lambda * beta});
  } else {
    out.push_back({"h_tilde", h});
  }
  return out;
}

std::string model_report(const ModelDerivation& m, const Symbols& s, bool latex) {
  const DerivedCoefficients& d = m.coefficients;
  std::ostringstream out;
  const auto show = [&](const ex& e) {
    std::ostringstream os;
    if (latex) os << GiNaC::latex;
    os << e;
    return os.str();
  };
  out << "model " << m.file.name << ": " << m.file.description << "\n";
  out << "file " << m.file.path << " (FNV-1a 64 " << hash_text(m.file.hash) << ")\n";
  out << "parameters:";
  for (const auto& p : m.file.parameters) out << " " << p.name << " = " << m.values.at(p.symbol);
  out << "\n";
  out << "case: " << (d.mean_flow ? "mean flow (translation-invariant, singular L_0): lambda and h_tilde = h - lambda beta"
                                   : "on-site (regular L_0): mean and second-harmonic terms solved directly, no lambda, h_tilde = h")
      << "\n";
  for (const auto& i : m.file.intermediates)
    out << "intermediate " << i.name << " = " << show(i.value) << "  (= " << ex_to<numeric>(evalf(m.values.at(i.symbol))).to_double() << ")\n";
  out << "branches (theta = 0 -> pi):";
  for (const auto& b : m.branches) {
    out << "\n  " << b.name << ": omega " << b.omega_at_zero << " -> " << b.omega_at_pi;
    if (!b.real) out << " (not real: " << b.problem << ")";
  }
  out << "\nderivation (D1 = 4 sin^2(theta/2), sigma = sin(theta); fields";
  for (const auto& f : m.file.model.fields) out << " " << f;
  out << "):\n";
  for (const auto& line : d.report) out << "  " << line << "\n";
  out << "coefficients (NLS: i A_tau + beta A_xi A0 + omega''/2 A_xixi - h |A|^2 A = 0; A = envelope of field "
      << m.file.model.fields[0] << ", u ~ eps (A E + c.c.)):\n";
  for (const auto& [name, e] : symbolic_coefficients(m, s)) out << "  " << name << " = " << show(e) << "\n";
  int passed = 0;
  out << "checks:\n";
  for (const auto& c : m.checks) {
    passed += c.passed;
    out << "  [" << (c.passed ? "PASS" : "FAIL") << "] " << c.name << "  (" << c.method << ": " << c.detail << ")\n";
  }
  out << passed << "/" << m.checks.size() << " checks passed; derivation " << m.derive_seconds << " s, checks "
      << m.check_seconds << " s\n";
  return out.str();
}

}  // namespace lrchain::derivation

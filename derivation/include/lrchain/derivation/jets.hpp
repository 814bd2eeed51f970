#pragma once
// Envelope jets: one symbol per derivative d_tau^p d_xi^q A_{k,j} of each field's envelope
// (DESIGN.md, "Notes for the derivation"). A_{k,-j} is the conjugate jet, an independent symbol.
#include <ginac/ginac.h>

#include <map>
#include <tuple>

namespace lrchain::derivation {

struct JetKey {
  int field, k, j, p, q;  // field index, eps order, harmonic, tau- and xi-derivative orders
  auto tie() const { return std::tie(field, k, j, p, q); }
  bool operator<(const JetKey& o) const { return tie() < o.tie(); }
};

class Jets {
 public:
  explicit Jets(std::vector<std::string> field_names) : names_(std::move(field_names)) {}
  // Symbol for d_tau^p d_xi^q of field `field`'s envelope at order eps^k, harmonic E^j.
  GiNaC::ex get(int field, int k, int j, int p = 0, int q = 0);
  bool decode(const GiNaC::ex& e, JetKey& key) const;
  // Total derivatives acting on any expression polynomial/rational in jets (chain rule).
  GiNaC::ex d_xi(const GiNaC::ex& e);
  GiNaC::ex d_tau(const GiNaC::ex& e);
  // Complex conjugate: numbers conjugated, jets (k,j) <-> (k,-j); all other symbols are real.
  GiNaC::ex conjugate(const GiNaC::ex& e);
  // All jet symbols occurring in e.
  std::vector<JetKey> jets_in(const GiNaC::ex& e) const;
  std::string name(const JetKey& key) const;

 private:
  GiNaC::ex derivative(const GiNaC::ex& e, int dp, int dq);
  std::vector<std::string> names_;
  std::map<JetKey, GiNaC::realsymbol> symbols_;
  std::map<std::string, JetKey> by_name_;
};

}  // namespace lrchain::derivation

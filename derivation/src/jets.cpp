#include "lrchain/derivation/jets.hpp"

#include <set>

namespace lrchain::derivation {

using namespace GiNaC;

std::string Jets::name(const JetKey& key) const {
  // e.g. A_u[1,1] with derivatives: A_u[1,1]_t1x2
  std::string s = names_.at(key.field) + "[" + std::to_string(key.k) + "," + std::to_string(key.j) + "]";
  if (key.p || key.q) s += "_t" + std::to_string(key.p) + "x" + std::to_string(key.q);
  return s;
}

ex Jets::get(int field, int k, int j, int p, int q) {
  const JetKey key{field, k, j, p, q};
  auto it = symbols_.find(key);
  if (it == symbols_.end()) {
    // Jets are declared real so that ex::conjugate() touches only the numbers (I -> -I);
    // conjugation of the envelopes is done explicitly by swapping j <-> -j.
    it = symbols_.emplace(key, realsymbol(name(key))).first;
    by_name_.emplace(name(key), key);
  }
  return it->second;
}

bool Jets::decode(const ex& e, JetKey& key) const {
  if (!is_a<symbol>(e)) return false;
  auto it = by_name_.find(ex_to<symbol>(e).get_name());
  if (it == by_name_.end()) return false;
  key = it->second;
  return true;
}

std::vector<JetKey> Jets::jets_in(const ex& e) const {
  std::set<JetKey> found;
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    JetKey key{};
    if (decode(*it, key)) found.insert(key);
  }
  return {found.begin(), found.end()};
}

ex Jets::derivative(const ex& e, int dp, int dq) {
  ex result = 0;
  for (const JetKey& key : jets_in(e)) {
    const ex sym = get(key.field, key.k, key.j, key.p, key.q);
    result += e.diff(ex_to<symbol>(sym)) * get(key.field, key.k, key.j, key.p + dp, key.q + dq);
  }
  return result;
}

ex Jets::d_xi(const ex& e) { return derivative(e, 0, 1); }
ex Jets::d_tau(const ex& e) { return derivative(e, 1, 0); }

ex Jets::conjugate(const ex& e) {
  exmap swap;
  for (const JetKey& key : jets_in(e))
    swap[get(key.field, key.k, key.j, key.p, key.q)] = get(key.field, key.k, -key.j, key.p, key.q);
  return e.conjugate().subs(swap, subs_options::no_pattern);
}

}  // namespace lrchain::derivation

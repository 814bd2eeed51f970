#include "lrchain/derivation/linear_algebra.hpp"

#include <sstream>
#include <stdexcept>

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

// Cofactor C_ij = (-1)^{i+j} det(L without row i and column j); the adjugate is C^T.
ex cofactor(const matrix& L, unsigned i, unsigned j) {
  const unsigned n = L.rows();
  if (n == 1) return 1;
  matrix minor(n - 1, n - 1);
  for (unsigned r = 0, rr = 0; r < n; ++r) {
    if (r == i) continue;
    for (unsigned c = 0, cc = 0; c < n; ++c) {
      if (c == j) continue;
      minor(rr, cc++) = L(r, c);
    }
    ++rr;
  }
  return ((i + j) % 2 ? -1 : 1) * minor.determinant();
}

std::size_t size_of(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str().size();
}

}  // namespace

std::vector<ex> null_vector(const matrix& L, bool right) {
  const unsigned n = L.rows();
  std::vector<ex> best;
  std::size_t best_size = 0;
  for (unsigned pick = 0; pick < n; ++pick) {
    // Right null vectors are columns of adj(L) = C^T, i.e. rows of C; left ones are columns of C.
    std::vector<ex> v;
    for (unsigned m = 0; m < n; ++m) v.push_back(right ? cofactor(L, pick, m) : cofactor(L, m, pick));
    const ex first = normal(v[0]);
    if (first.is_zero()) continue;
    std::size_t total = 0;
    for (auto& e : v) {
      e = normal(e / first);
      total += size_of(e);
    }
    if (best.empty() || total < best_size) {
      best = v;
      best_size = total;
    }
  }
  if (best.empty()) throw std::runtime_error("no null vector with a nonzero first entry");
  return best;
}

std::vector<ex> particular_solution(const matrix& L, const std::vector<ex>& rhs) {
  const unsigned n = L.rows();
  std::vector<ex> p(n, 0);
  if (n == 1) return p;
  matrix sub(n - 1, n - 1), b(n - 1, 1);
  for (unsigned r = 1; r < n; ++r) {
    for (unsigned c = 1; c < n; ++c) sub(r - 1, c - 1) = L(r, c);
    b(r - 1, 0) = rhs[r];
  }
  const matrix x = sub.inverse().mul(b);
  for (unsigned r = 1; r < n; ++r) p[r] = normal(x(r - 1, 0));
  return p;
}

}  // namespace lrchain::derivation

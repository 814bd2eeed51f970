// Overlaps of a model lattice's one-sided contacts (contact_bonds.hpp).
#include "lrchain/sim/dark/contact_bonds.hpp"

#include <cstddef>

namespace lrchain::sim::dark {

// s_n = offset + sum_k c_k q[v_k][n + shift_k] on a periodic ring, and ds_n/dt from qdot.
void contact_overlaps(const ContactBonds& bonds, int sites, const double* q, const double* qdot, double* overlap,
                      double* rate) {
  const std::size_t N = std::size_t(sites);
  for (std::size_t j = 0; j < bonds.size(); ++j) {
    double* s = overlap + j * N;
    double* ds = rate + j * N;
    for (std::size_t n = 0; n < N; ++n) {
      s[n] = bonds[j].offset;
      ds[n] = 0.0;
    }
    for (const auto& term : bonds[j].terms) {
      const std::size_t base = std::size_t(term.variable) * N;
      const long shift = ((long(term.shift) % long(N)) + long(N)) % long(N);
      for (std::size_t n = 0; n < N; ++n) {
        const std::size_t at = base + (n + std::size_t(shift)) % N;
        s[n] += term.coefficient * q[at];
        ds[n] += term.coefficient * qdot[at];
      }
    }
  }
}

}  // namespace lrchain::sim::dark

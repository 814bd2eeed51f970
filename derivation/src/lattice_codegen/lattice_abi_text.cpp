// The fixed parts of generated lattice sources (see lattice_abi_text.hpp).
#include "lattice_abi_text.hpp"

namespace lrchain::derivation {

std::string helpers_text() {
  return R"text(#pragma GCC diagnostic ignored "-Wunused-parameter"

// Vectorised loops: target clones, no errno (packed sqrt), no reassociation (all clones agree).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define LRCHAIN_KERNEL [[maybe_unused]] static __attribute__((target_clones("avx512f", "avx2", "default"), \
    optimize("fast-math", "no-associative-math", "no-reciprocal-math", "fp-contract=off")))
#else
#define LRCHAIN_KERNEL [[maybe_unused]] static
#endif

)text";
}

std::string workspace_text() {
  return R"text(// Padded copies of the variables (kPad ghost sites each side), bond arrays (kBondPad ghosts)
// and site forces of the strain form (one ghost site on the left), all in the caller's memory.
struct Workspace {
  static long variable_stride(long n) { return n + 2 * kPad; }
  static long bond_stride(long n) { return n + 2 * kBondPad; }
  static long size(long n) { return 2 * kVariables * variable_stride(n) + 2 * kBonds * bond_stride(n) + kVariables * (n + 1); }

  Workspace(double* work, long n) {
    for (int g = 0; g < kVariables; ++g) {
      x[g] = work + g * variable_stride(n) + kPad;
      dx[g] = work + (kVariables + g) * variable_stride(n) + kPad;
    }
    double* bonds = work + 2 * kVariables * variable_stride(n);
    for (int j = 0; j < kBonds; ++j) {
      b[j] = bonds + j * bond_stride(n) + kBondPad;
      db[j] = bonds + (kBonds + j) * bond_stride(n) + kBondPad;
    }
    double* sites = bonds + 2 * kBonds * bond_stride(n);
    for (int g = 0; g < kVariables; ++g) a[g] = sites + g * (n + 1) + 1;
  }

  // Copies q (kVariables arrays of n) into padded arrays: periodic images, or zeros outside
  // (free ends: copies of field 0's last entry on the right, zero strains beyond the chain).
  static void pad(double* const* padded, const double* q, long n, int ends) {
    const bool periodic = ends == LRCHAIN_LATTICE_ENDS_PERIODIC;
    const double right = ends == LRCHAIN_LATTICE_ENDS_FREE ? q[n - 1] : 0.0;
    for (int g = 0; g < kVariables; ++g) {
      double* p = padded[g];
      const double* source = q + g * n;
      std::memcpy(p, source, std::size_t(n) * sizeof(double));
      for (long i = 1; i <= kPad; ++i) {
        p[-i] = periodic ? source[((-i) % n + n) % n] : 0.0;
        p[n - 1 + i] = periodic ? source[(n - 1 + i) % n] : right;
      }
    }
  }

  double* const* out(double* o, long n) {
    for (int g = 0; g < kVariables; ++g) output[g] = o + g * n;
    return output;
  }

  double* x[kVariables];
  double* dx[kVariables];
  double* b[kBonds];
  double* db[kBonds];
  double* a[kVariables];
  double* output[kVariables];
};

// Free ends: zeroes the instances i in [lo, hi) of each bond j outside first[j] <= i <= n - 1 - reach[j]
// (those touching a bead beyond the chain).
[[maybe_unused]] void free_ends(double* const* b, int bonds, const long* first, const long* reach, long lo, long hi, long n) {
  for (int j = 0; j < bonds; ++j) {
    double* b_j = b[j];
    for (long i = lo; i < hi && i < first[j]; ++i) b_j[i] = 0.0;
    for (long i = n - reach[j] > lo ? n - reach[j] : lo; i < hi; ++i) b_j[i] = 0.0;
  }
}

// Strain form: r'' = a_0[n] - a_0[n-1], w_f'' = a_f[n] - a_0[n].
LRCHAIN_KERNEL void strain_differences(double* const* a, double* out, long n) {
  const double* __restrict a0 = a[0];
  double* __restrict r = out;
  for (long i = 0; i < n; ++i) r[i] = a0[i] - a0[i - 1];
  for (int g = 1; g < kVariables; ++g) {
    const double* __restrict ag = a[g];
    double* __restrict w = out + g * n;
    for (long i = 0; i < n; ++i) w[i] = ag[i] - a0[i];
  }
}

)text";
}

}  // namespace lrchain::derivation

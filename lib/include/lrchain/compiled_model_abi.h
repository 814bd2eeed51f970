/* The ABI of a compiled model (docs/models.md): what the model compiler emits and the runtime loads,
 * one header both include (the generator embeds its text, derivation/CMakeLists.txt). Plain C so
 * that a model compiled at run time can be loaded with dlopen.
 *
 * A model file compiled at run time is ONE shared object (one cache entry) exporting
 *   const char lrchain_model_metadata[]        the model's description (JSON: parameters, branches)
 *   const char lrchain_model_file_sha256[]     the SHA-256 of the model file's bytes
 *   const int lrchain_compiled_model_abi_version  LRCHAIN_COMPILED_MODEL_ABI_VERSION
 *   lrchain_model_intermediates, _dispersion, _nls, _harmonics  the NLS evaluators (the
 *       lrchain_model_*_function types below; lrchain/model.hpp's ModelEvaluators)
 *   const struct lrchain_lattice_kernels* lrchain_lattice_<model>(void)  the lattice kernels.
 * Shipped models compile the same kernel table into lrchain_sim and their evaluators into lrchain.
 *
 * Lattice kernels. State layout: field-major arrays of `sites` entries per variable. Displacement form: variable f
 * is field f's displacement u_f[n]. Strain form (translation-invariant models): variable 0 is
 * r[n] = u_0[n] - u_0[n-1], variable f >= 1 is w_f[n] = u_f[n] - u_0[n].
 * Ends: periodic != 0 wraps the sites. Otherwise, displacement form: every variable is 0 outside
 * the chain (fixed walls); strain form: free ends, the chain of beads u_0[-1..sites-1] and
 * u_f[0..sites-1] (f >= 1) without the bond instances (function calls) that touch any other bead;
 * polynomial terms of the forces see zero strain and relative displacement beyond the ends.
 * The energy density takes `ends`: LRCHAIN_LATTICE_ENDS_FIXED, _PERIODIC, or _FREE: the strain
 * form's free chain in displacements measured from bead u_0[-1] (whose kinetic energy is the
 * caller's), with the same bond instances dropped.
 * `work` holds workspace_size(sites) doubles; nothing allocates. */
#ifndef LRCHAIN_COMPILED_MODEL_ABI_H
#define LRCHAIN_COMPILED_MODEL_ABI_H

/* 4: evaluators and lattice kernels in one object (before: two objects, lattice ABI 3). */
#define LRCHAIN_COMPILED_MODEL_ABI_VERSION 4

/* The NLS evaluators (q: the intermediates of the parameters p; D1 = 4 sin^2(theta/2), sigma = sin theta). */
typedef void (*lrchain_model_intermediates_function)(const double* p, double* q);
typedef void (*lrchain_model_dispersion_function)(double D1, double sigma, const double* q, double* w);
typedef void (*lrchain_model_nls_function)(double D1, double sigma, double omega, const double* q, double* out);
typedef void (*lrchain_model_harmonics_function)(double D1, double sigma, double omega, const double* q, double* out);

#define LRCHAIN_LATTICE_ENDS_FIXED 0
#define LRCHAIN_LATTICE_ENDS_PERIODIC 1
#define LRCHAIN_LATTICE_ENDS_FREE 2

typedef void (*lrchain_lattice_accelerations)(const double* parameters, long sites, int periodic,
                                              const double* q, double* a, double* work);
typedef void (*lrchain_lattice_jacobian_action)(const double* parameters, long sites, int periodic,
                                                const double* q, const double* dq, double* da,
                                                double* work);
typedef void (*lrchain_lattice_energy_density)(const double* parameters, long sites, int ends,
                                               const double* u, const double* velocity, double* e,
                                               double* work);

/* The one-sided contacts of one lattice form (a `[functions]` law with `contact`): contact bond j's
 * overlap at site n is s_n = offsets[j] + sum_k coefficients[t] q[variables[t]][n + shifts[t]] over its
 * term_counts[j] terms t (the terms of bond after bond), periodic in n; the contact is lost where
 * s_n < 0, and the accelerations clamp exactly this s_n. term_counts[j] = -1: the overlap is not
 * linear in the variables (no terms). forms() evaluates offsets and coefficients at the parameters. */
struct lrchain_lattice_contacts {
  int bonds;
  const char* const* names; /* the law and its argument in the fields, e.g. "F(u[n+1] - u[n])" */
  const int* term_counts;
  const int* variables;
  const int* shifts;
  void (*forms)(const double* parameters, double* offsets, double* coefficients);
};

struct lrchain_lattice_kernels {
  int abi_version;
  const char* model_name;
  int fields;
  int parameter_count;
  const char* const* parameter_names; /* in the model file's order: the `parameters` argument */
  void (*masses)(const double* parameters, double* mass); /* mass of each field */
  long (*workspace_size)(long sites);
  lrchain_lattice_accelerations displacement_accelerations;
  lrchain_lattice_jacobian_action displacement_jacobian_action;
  lrchain_lattice_accelerations strain_accelerations;     /* null for on-site models */
  lrchain_lattice_jacobian_action strain_jacobian_action; /* null for on-site models */
  lrchain_lattice_energy_density energy_density;          /* displacement form; null if no potential */
  const struct lrchain_lattice_contacts* displacement_contacts; /* null: no one-sided contact */
  const struct lrchain_lattice_contacts* strain_contacts;       /* null: none, or an on-site model */
};

#endif

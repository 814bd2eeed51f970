#pragma once
// A lattice model loaded for numerics (docs/models.md): its name, file hash, parameters with their
// ranges, branch names and the emitted double evaluators (shipped models: compiled into the
// library from lib/include/lrchain/generated/model_*.hpp; a user's file: compiled at run time and
// loaded by the model compiler). The library never runs the symbolic derivation itself.
#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lrchain/coefficients.hpp"
#include "lrchain/index.hpp"

namespace lrchain {

// Outputs of a model's NLS evaluator, in this order (ModelEvaluators::nls writes out[0..count)).
enum ModelOutput : int {
  out_group_velocity, out_gamma, out_curvature, out_beta, out_nonresonance1, out_nonresonance2, out_h, out_lambda,
  out_h_tilde, out_h_tilde_numerator, out_dispersion, out_nonresonance1_scale, out_nonresonance2_scale,
  model_output_count
};

// Outputs of a model's harmonics evaluator for field f: out[harmonic_output_count f + HarmonicOutput]:
// the second-order terms of the multiple-scale expansion
//   u_f = eps (A_{1,1} K_f E + c.c.) + eps^2 (A_{2,2,f} E^2 + A_{2,1,f} E + c.c. + A_{2,0,f}) + ...,
// E = e^{i(n theta - omega t)}: the second harmonic A_{2,2,f} / A_{1,1}^2, the mean A_{2,0,f} /
// |A_{1,1}|^2 (translation-invariant models: field 0's mean is the mean flow, lambda, reported as 0;
// other fields' is their offset from it) and the gradient term G_f of A_{2,1,f} = K_f A_{2,1} + G_f
// d_xi A_{1,1} (G_0 = 0; G_f = -i dK_f/dtheta along the branch).
enum HarmonicOutput : int {
  harmonic_second_real, harmonic_second_imaginary, harmonic_mean, harmonic_gradient_real, harmonic_gradient_imaginary,
  harmonic_output_count
};

// Highest degree in omega^2 of det M a model may have (number of fields).
inline constexpr Index kMaxModelDegree = 6;

// The same evaluators held by an object: a user model evaluated through GiNaC in double
// precision when no C++ compiler is available (lrchain_model_compiler). Safe to call concurrently.
class ModelEvaluatorObject {
 public:
  virtual ~ModelEvaluatorObject() = default;
  virtual void intermediates(const double* parameters, double* q) const = 0;
  virtual void dispersion(double D1, double sigma, const double* q, double* coefficients) const = 0;
  virtual void nls(double D1, double sigma, double omega, const double* q, double* out) const = 0;
  virtual void harmonics(double D1, double sigma, double omega, const double* q, double* out) const = 0;
};

// The evaluator functions emitted for a model. q holds the parameter values followed by the named
// intermediates (e.g. K2, K3, K4); D1 = 4 sin^2(theta/2), sigma = sin(theta).
struct ModelEvaluators {
  void (*intermediates)(const double* parameters, double* q) = nullptr;  // q = parameters, intermediates
  void (*dispersion)(double D1, double sigma, const double* q, double* coefficients) = nullptr;  // det M, ascending in omega^2
  void (*nls)(double D1, double sigma, double omega, const double* q, double* out) = nullptr;     // ModelOutput order
  void (*harmonics)(double D1, double sigma, double omega, const double* q, double* out) = nullptr;  // HarmonicOutput per field
  std::shared_ptr<const ModelEvaluatorObject> object;  // used instead when the functions are null

  // The functions when emitted and compiled, else the object.
  void evaluate_intermediates(const double* parameters, double* q) const {
    if (intermediates) intermediates(parameters, q);
    else object->intermediates(parameters, q);
  }
  void evaluate_dispersion(double D1, double sigma, const double* q, double* coefficients) const {
    if (dispersion) dispersion(D1, sigma, q, coefficients);
    else object->dispersion(D1, sigma, q, coefficients);
  }
  void evaluate_nls(double D1, double sigma, double omega, const double* q, double* out) const {
    if (nls) nls(D1, sigma, omega, q, out);
    else object->nls(D1, sigma, omega, q, out);
  }
  void evaluate_harmonics(double D1, double sigma, double omega, const double* q, double* out) const {
    if (harmonics) harmonics(D1, sigma, omega, q, out);
    else object->harmonics(D1, sigma, omega, q, out);
  }
};

// One parameter of a model file: name, default and valid range.
struct ModelParameter {
  std::string name, range_text;
  double default_value = 0;
  bool has_lower = false, has_upper = false, lower_closed = false, upper_closed = false;
  double lower = 0, upper = 0;
  bool contains(double value) const;
};

// Everything the numerics need about one model.
struct ModelDefinition {
  std::string name, description;
  std::uint64_t file_hash = 0;  // FNV-1a 64 of the model file's bytes (displayed; not an identity)
  std::string file_sha256;      // SHA-256 (hex) of the model file's bytes: what identifies the file
  std::vector<ModelParameter> parameters;
  std::vector<std::string> intermediates;  // names of the named Taylor coefficients (q after the parameters)
  std::vector<std::string> branch_names;   // in increasing frequency
  bool mean_flow = true;                   // translation-invariant (lambda, h_tilde = h - lambda beta); else on-site
  Index degree = 1;                        // degree of det M in omega^2 (= number of fields)
  ModelEvaluators evaluators;
  std::shared_ptr<const void> keep_alive;  // owner of the evaluator code (a loaded shared object), if any

  // The paper's chain: the shipped model "resonant_chain", identified by its file's SHA-256 (a
  // user's copy of the file counts, a file merely named so does not). The one test that chooses the
  // resonant chain's specialised evaluators (coefficients(), coefficients_batch()).
  bool is_resonant_chain() const;
};

// The shipped models (models/*.toml) with their compiled-in evaluators, sorted by name.
const std::vector<ModelDefinition>& shipped_models();
// The shipped model called `name`, or nullptr.
const ModelDefinition* find_shipped_model(std::string_view name);

// A model with parameter values: the evaluators' input vector q is computed once here.
class Model {
 public:
  // Defaults overridden by `values` (name, value); throws InvalidParameter for an unknown name or a
  // value outside the parameter's range.
  explicit Model(std::shared_ptr<const ModelDefinition> definition,
                 const std::vector<std::pair<std::string, double>>& values = {});
  const ModelDefinition& definition() const { return *definition_; }
  const std::string& name() const { return definition_->name; }
  std::uint64_t file_hash() const { return definition_->file_hash; }
  // Parameter values in the file's order, then the named intermediates.
  const std::vector<double>& inputs() const { return q_; }
  double parameter(std::string_view name) const;
  // Index of a branch name (throws InvalidParameter("branch", ...) naming the model's branches).
  Index branch(std::string_view name) const;
  // branch(name), or the model's only branch when name is empty (several: InvalidParameter("branch",
  // "is required") naming them).
  Index branch_or_only(std::string_view name) const;
  // The resonant chain's alpha, delta0, kappa, rho when the model is that chain
  // (ModelDefinition::is_resonant_chain), else empty: coefficients() then takes the specialised path.
  const std::optional<Params>& resonant_chain_params() const { return resonant_chain_params_; }
  // The resonant chain's Branch of branch index `branch` (precondition: resonant_chain_params()).
  Branch resonant_chain_branch(Index branch) const { return branch == optical_branch_ ? Branch::optical : Branch::acoustic; }
  // K2, K3, K4 of resonant_chain_params() (taylor_coefficients, as coefficients(Params) computes them).
  const TaylorCoefficients& resonant_chain_taylor_coefficients() const { return resonant_chain_K_; }

 private:
  std::shared_ptr<const ModelDefinition> definition_;
  std::vector<double> q_;
  std::optional<Params> resonant_chain_params_;
  TaylorCoefficients resonant_chain_K_{};
  Index optical_branch_ = -1;
};

// The shipped model `name` (InputError if there is none) with the given parameter values.
Model shipped_model(std::string_view name, const std::vector<std::pair<std::string, double>>& values = {});

// The resonant chain (the shipped model "resonant_chain") at `p`: the paper's chain as a Model.
Model resonant_chain_model(const Params& p);

// "0x" + 16 hex digits.
std::string model_hash_text(std::uint64_t hash);

// FNV-1a 64 of `bytes` (continuing from `hash`): the short hash model files are shown with (JSON
// "file_hash"); files are identified by file_sha256.
std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash = 14695981039346656037ull);

// The largest model file lrchain reads (bytes); the shipped ones are under 4 KiB.
inline constexpr std::size_t kMaxModelFileBytes = 1 << 20;

// The bytes of the model file `path`, read by every front end: InputError naming the file unless it
// is a regular file (not a directory, FIFO, device or socket) of at most kMaxModelFileBytes.
std::string read_model_file_bytes(const std::string& path);

// The shipped model whose file has the bytes `bytes` (compared by SHA-256), or nullptr.
const ModelDefinition* find_shipped_model_by_bytes(std::string_view bytes);

// A model file read once by the model loader: the path that names it, its bytes and their SHA-256
// (64 hex digits), handed on to the run-time compiler so that nothing reads or hashes it again.
struct ModelFileContent {
  std::string path;
  std::string bytes;
  std::string sha256;
};

// read_model_file_bytes(path) with the bytes' SHA-256.
ModelFileContent read_model_file(const std::string& path);

// The shipped model whose file's SHA-256 is `sha256` (64 hex digits), or nullptr.
const ModelDefinition* find_shipped_model_by_sha256(std::string_view sha256);

// NLS coefficients of `model` on branch `branch` (index into branch_names) at theta in (-pi, pi]:
// omega is the branch's root of det M = 0 in omega^2. lambda is NaN (no mean flow) for on-site
// models. Throws InvalidParameter for theta out of range or where the branch has no real,
// positive frequency (theta = 0 on an acoustic branch). Allocation-free. The resonant chain
// (Model::resonant_chain_params) goes through its specialised evaluators: bit-identical to
// coefficients(Params, Branch, theta).
NlsCoefficients coefficients(const Model& model, Index branch, double theta);

// The same through the model's own emitted evaluators, the resonant chain's too (no dispatch; the
// two agree to rounding, ~1e-13). The lattice runs of a loaded model (bright, ring, dark ansatz,
// Bloch waves, second-order terms) evaluate their NLS ansatz with these, so that their outputs for
// the chain as a model file are the same bits as before lib chose the specialised path.
NlsCoefficients coefficients_from_evaluators(const Model& model, Index branch, double theta);

// The same from the evaluator input vector q (parameters, then intermediates) through the model's
// emitted evaluators (the resonant chain's too: no dispatch) without any check of theta or branch: false (and `out` untouched) where det M has no real root or the branch's
// omega^2 is not positive. For loops over theta or a parameter (regime maps). Allocation-free.
bool coefficients_at(const ModelDefinition& definition, const double* q, Index branch, double theta,
                     NlsCoefficients& out) noexcept;

// The second-order terms of the multiple-scale expansion of `model` on `branch` at theta, per field
// (HarmonicOutput): the second harmonic per unit A^2, the mean per unit |A|^2 and the gradient term
// per unit dA/dn, where A is the envelope of field 0 (u_0 = A E + c.c. + ...). Same checks and exceptions as coefficients().
struct SecondOrderTerms {
  std::vector<std::complex<double>> second_harmonic;  // A_{2,2,f} / A_{1,1}^2
  std::vector<double> mean;                           // A_{2,0,f} / |A_{1,1}|^2 (mean flow: offset from it)
  std::vector<std::complex<double>> kernel_gradient;  // G_f: A_{2,1,f} = K_f A_{2,1} + G_f d_xi A_{1,1}
};
SecondOrderTerms second_order_terms(const Model& model, Index branch, double theta);

// Roots in omega^2 of the polynomial sum_k coefficients[k] w^k (k = 0..degree, degree <=
// kMaxModelDegree), real parts ascending, into roots[0..degree); returns false when a root is not
// real. Allocation-free. (Raw arrays like the evaluators above: the C interface of generated code.)
bool omega_squared_roots(const double* coefficients, Index degree, double* roots);

}  // namespace lrchain

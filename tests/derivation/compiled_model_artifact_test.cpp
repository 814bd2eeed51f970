// One compiled artifact per model file (lrchain/compiled_model_abi.h, docs/models.md): a user's
// file is compiled once into one cache entry whose one object holds both its NLS evaluators and its
// lattice kernels; a second load (coefficients or lattice) finds that entry and compiles nothing.
// The file is models/fput.toml renamed (the smallest shipped model: a cold compile takes about a
// second), so the shipped evaluators and kernels are the independent reference.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/model_compiler.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "scratch_cache.hpp"

namespace fs = std::filesystem;
using namespace lrchain;

namespace {

// models/fput.toml with its model named "mine" (a file that is not a shipped one).
ModelFileContent renamed_fput(const fs::path& path) {
  std::ifstream in(fs::path(LRCHAIN_SOURCE_DIR) / "models" / "fput.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string from = "name = \"fput\"";
  s.replace(s.find(from), from.size(), "name = \"mine\"");
  std::ofstream(path) << s;
  return read_model_file(path.string());
}

// The names of the files in the model cache.
std::vector<std::string> cache_files(const fs::path& cache) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(cache)) names.push_back(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("compiled model: one file compiles once into one cache entry holding its evaluators and lattice kernels" *
          doctest::timeout(600)) {
  if (!model_compiler_available()) return;
  test::ScratchCache scratch("lrchain-artifact-test");
  const ModelFileContent file = renamed_fput(scratch.dir / "mine.toml");
  CompiledModelInfo info;
  const CompiledModel compiled = compile_model(file, &info);
  CHECK_FALSE(info.from_cache);
  REQUIRE(compiled.definition);
  REQUIRE(compiled.kernels);
  // One object and its manifest: evaluators and kernels are not two entries.
  std::vector<std::string> files = cache_files(scratch.cache());
  REQUIRE(files.size() == 2);
  CHECK(std::count_if(files.begin(), files.end(), [](const std::string& n) { return n.rfind("model-", 0) == 0; }) == 2);
  CHECK(fs::path(files[0]).extension() != fs::path(files[1]).extension());  // .so and .manifest
  CHECK(compiled.kernels->abi_version == LRCHAIN_COMPILED_MODEL_ABI_VERSION);
  CHECK(std::string(compiled.kernels->model_name) == "mine");
  CHECK(compiled.kernels->parameter_count == int(compiled.definition->parameters.size()));

  // The evaluators: the shipped fput's coefficients (compiled-in evaluators, the reference).
  const Model mine(compiled.definition), shipped = shipped_model("fput");
  const auto a = coefficients(mine, 0, 1.0), b = coefficients(shipped, 0, 1.0);
  CHECK(a.h == doctest::Approx(b.h).epsilon(1e-12));
  CHECK(a.curvature == doctest::Approx(b.curvature).epsilon(1e-12));

  // The kernels: the shipped fput's accelerations on one state (the same generator and force law).
  const lrchain_lattice_kernels* reference = sim::shipped_lattice_kernels("fput");
  REQUIRE(reference);
  constexpr long sites = 16;
  // The kernels take the parameters in the file's order: the first entries of the evaluators' inputs.
  const std::vector<double> parameters(mine.inputs().begin(), mine.inputs().begin() + compiled.kernels->parameter_count);
  std::vector<double> q(16), a_mine(16), a_shipped(16);
  for (long n = 0; n < sites; ++n) q[std::size_t(n)] = 0.1 * std::sin(0.7 * double(n) + 0.3);
  std::vector<double> work_mine(std::size_t(compiled.kernels->workspace_size(sites))),
      work_shipped(std::size_t(reference->workspace_size(sites)));
  compiled.kernels->displacement_accelerations(parameters.data(), sites, 1, q.data(), a_mine.data(), work_mine.data());
  reference->displacement_accelerations(parameters.data(), sites, 1, q.data(), a_shipped.data(), work_shipped.data());
  for (std::size_t n = 0; n < q.size(); ++n) CHECK(a_mine[n] == doctest::Approx(a_shipped[n]).epsilon(1e-14));

  // A second load (any job: coefficients or a lattice run) finds the one entry and compiles nothing.
  CompiledModelInfo again;
  const CompiledModel loaded = compile_model(file, &again);
  CHECK(again.from_cache);
  CHECK(again.library == info.library);
  REQUIRE(loaded.kernels);
  CHECK(compile_model_lattice(file, &again) != nullptr);
  CHECK(again.from_cache);
  CHECK(cache_files(scratch.cache()).size() == 2);
}

// The one model loader (jobs::ModelSource) with a recording compiler injected: shipped models by
// name or by their file's bytes never reach the compiler; a user's file is read and hashed once and
// handed to it as read, compiled once: its evaluators and lattice kernels from one artifact.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/sha256.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "../support/scratch_dir.hpp"

namespace {

using lrchain::ModelFileContent;
namespace jobs = lrchain::jobs;

// Records every call; compiles nothing: a user's file gets the shipped FPUT chain's evaluators and
// kernels (one "artifact") under the file's own hash (the test's files are copies of models/fput.toml).
struct RecordingCompiler : jobs::ModelCompiler {
  mutable std::vector<std::string> calls;
  mutable std::vector<ModelFileContent> files;

  jobs::CompiledCode compile(const ModelFileContent& file) const override {
    calls.push_back("compile");
    files.push_back(file);
    auto d = std::make_shared<lrchain::ModelDefinition>(*lrchain::find_shipped_model("fput"));
    d->file_sha256 = file.sha256;
    jobs::CompiledCode code;
    code.definition = d;
    code.kernels = {std::shared_ptr<const lrchain_lattice_kernels>(), lrchain::sim::shipped_lattice_kernels("fput")};
    code.from_cache = true;
    code.library = "/cache/model.so";
    return code;
  }
  void refuse_lattice(const ModelFileContent& file) const override {
    calls.push_back("refuse_lattice");
    files.push_back(file);
  }
  void check_lattice(const ModelFileContent& file) const override {
    calls.push_back("check_lattice");
    files.push_back(file);
  }
};

std::string shipped_fput_text() {
  std::ifstream in(std::filesystem::path(LRCHAIN_SOURCE_DIR) / "models/fput.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("model source: a shipped model by name or by its file's bytes never reaches the compiler" * doctest::test_suite("fast")) {
  const auto compiler = std::make_shared<RecordingCompiler>();
  const jobs::ModelSource by_name("klein_gordon", "--model", compiler);
  CHECK(by_name.definition().get() == lrchain::find_shipped_model("klein_gordon"));
  CHECK(by_name.path().empty());
  const jobs::ModelSource by_file(std::string(LRCHAIN_SOURCE_DIR) + "/models/fput.toml", "--model", compiler, true);
  CHECK(by_file.definition().get() == lrchain::find_shipped_model("fput"));
  const jobs::LatticeCode& code = by_file.lattice();
  CHECK(code.compiled_in);
  CHECK(code.kernels.get() == lrchain::sim::shipped_lattice_kernels("fput"));
  CHECK(jobs::lattice_code_json(code, false) == nlohmann::json::parse(R"({"compiled_in": true, "from_cache": null, "library": null})"));
  CHECK(compiler->calls.empty());
  // The shipped model named whatever files exist; an unknown name lists the shipped ones.
  CHECK(jobs::ModelSource::shipped("resonant_chain", "--model").definition()->is_resonant_chain());
  CHECK_THROWS_WITH_AS(jobs::ModelSource("kleingordon", "load_model:", compiler),
                       doctest::Contains("load_model: no shipped model 'kleingordon' (shipped: "), lrchain::InputError);
}

TEST_CASE("model source: a user's file is read and hashed once and compiled once, evaluators and kernels together" * doctest::test_suite("fast")) {
  const auto dir = lrchain::test::scratch_directory("model-source");
  const std::string bytes = shipped_fput_text() + "# a user's copy\n";
  const std::string path = (dir / "mine.toml").string();
  std::ofstream(path) << bytes;
  const auto compiler = std::make_shared<RecordingCompiler>();
  const jobs::ModelSource source(path, "--model", compiler, true);
  // The lattice check comes first (a lattice run refuses before compiling).
  REQUIRE(compiler->calls == std::vector<std::string>{"check_lattice", "compile"});
  CHECK(compiler->files[1].path == path);
  CHECK(compiler->files[1].bytes == bytes);
  CHECK(compiler->files[1].sha256 == lrchain::sha256_hex(bytes));
  // The file changes on disk: the kernels are those of the one compile of the bytes read.
  std::ofstream(path) << "name = \"other\"\n";
  const jobs::LatticeCode& code = source.lattice();
  CHECK(&source.lattice() == &code);  // loaded once
  CHECK(compiler->calls == std::vector<std::string>{"check_lattice", "compile"});  // no second compile
  CHECK(code.kernels.get() == lrchain::sim::shipped_lattice_kernels("fput"));
  CHECK_FALSE(code.compiled_in);
  CHECK(jobs::lattice_code_json(code, false) ==
        nlohmann::json::parse(R"({"compiled_in": false, "from_cache": true, "library": "/cache/model.so"})"));
  const lrchain::Model model = source.model({{"a", 0.5}});
  CHECK(model.parameter("a") == 0.5);
  std::filesystem::remove_all(dir);
}

TEST_CASE("model source: without a compiler a user's file is refused naming the file" * doctest::test_suite("fast")) {
  const auto dir = lrchain::test::scratch_directory("model-source-none");
  const std::string path = (dir / "mine.toml").string();
  std::ofstream(path) << shipped_fput_text() << "# a user's copy\n";
  CHECK_THROWS_WITH_AS(jobs::ModelSource(path, "--model", nullptr),
                       ("--model " + path + ": not a shipped model file, and this build has no model compiler "
                        "(configure with LRCHAIN_BUILD_DERIVATION=ON)").c_str(),
                       lrchain::InputError);
  // A directory is refused by the reader, after the front end's label.
  const std::string directory_refused = "load_model: " + dir.string() + ": a directory";
  CHECK_THROWS_WITH_AS(jobs::ModelSource(dir.string(), "load_model:", nullptr), doctest::Contains(directory_refused.c_str()),
                       lrchain::InputError);
  std::filesystem::remove_all(dir);
}

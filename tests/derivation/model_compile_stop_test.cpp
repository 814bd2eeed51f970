// Stopping and failing run-time compiles of a model file (docs/models.md, "The cache is checked
// before anything in it is loaded"): a stop flag (SIGINT/SIGTERM in the CLI, Ctrl-C in Python) ends
// the derivation between its steps and kills the compiler's whole process group (a fake compiler's
// grandchild `sleep` plays cc1plus), leaving nothing in the cache; a failing compiler is one line
// with its exit status and stderr; a directory at an entry's manifest is refused before compiling;
// and an evaluation that a parameter value breaks names that parameter, not theta.
#include <doctest/doctest.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "lrchain/derivation/derivation_stop.hpp"
#include "lrchain/derivation/model_derivation.hpp"
#include "lrchain/derivation/model_file.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/model_compiler.hpp"
#include "lrchain/process.hpp"
#include "../support/process_checks.hpp"
#include "scratch_cache.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using test::process_gone;
using test::wait_for_pid_file;

namespace {

struct Scratch : test::ScratchCache {
  Scratch() : ScratchCache("lrchain-compile-stop") {}
};

// A Morse chain, F(r) = 2 a b (exp(-a r) - exp(-2 a r)), with the law's factor `extra` (line 8).
std::string morse_model(const std::string& extra = "1") {
  return "name = \"morse\"\n"
         "description = \"Morse chain\"\n"
         "[parameters]\n"
         "a = { default = \"1\", range = \"(0, inf)\" }\n"
         "b = { default = \"1\", range = \"(0, inf)\" }\n"
         "[functions.F]\n"
         "argument = \"r\"\n"
         "expression = \"2*a*b*(exp(-a*r) - exp(-2*a*r))*" + extra + "\"\n"
         "[[field]]\n"
         "name = \"u\"\n"
         "mass = \"1\"\n"
         "force = \"F(u[n+1] - u[n]) - F(u[n] - u[n-1])\"\n";
}

// A three-field mass-in-mass-in-mass chain whose inner springs carry a sum of parameters in the
// forces themselves: `lrchain derive` takes 16 s on an idle 2-core machine (measured), long enough to
// be stopped at 0.7 s. A one-field law within the term bound derives in under 0.6 s, which a signal
// at 0.7 s can miss.
std::string slow_three_field_model() {
  return "name = \"mass_in_mass3_slow\"\n"
         "[parameters]\n"
         "a1 = { default = \"1/4\", range = \"(-inf, inf)\" }\n"
         "b1 = { default = \"1/2\", range = \"(-inf, inf)\" }\n"
         "k2 = { default = 1, range = \"(0, inf)\" }\n"
         "m2 = { default = \"1/2\", range = \"(0, inf)\" }\n"
         "k3 = { default = \"1/2\", range = \"(0, inf)\" }\n"
         "g3 = { default = 1, range = \"(-inf, inf)\" }\n"
         "m3 = { default = \"1/4\", range = \"(0, inf)\" }\n"
         "[functions.F]\n"
         "argument = \"r\"\n"
         "expression = \"r + a1*r^2 + b1*r^3\"\n"
         "[functions.G]\n"
         "argument = \"s\"\n"
         "expression = \"k3*s + g3*s^3\"\n"
         "[[field]]\n"
         "name = \"u\"\n"
         "mass = \"1\"\n"
         "force = \"F(u[n+1] - u[n]) - F(u[n] - u[n-1]) - k2*(1 + a1 + b1)*(u[n] - v[n])\"\n"
         "[[field]]\n"
         "name = \"v\"\n"
         "mass = \"m2\"\n"
         "force = \"k2*(1 + a1 + b1)*(u[n] - v[n]) - G(v[n] - w[n])\"\n"
         "[[field]]\n"
         "name = \"w\"\n"
         "mass = \"m3\"\n"
         "force = \"G(v[n] - w[n])\"\n";
}

// LRCHAIN_MODEL_CXX for the scope of a test.
struct ModelCompiler {
  explicit ModelCompiler(const std::string& program) { ::setenv("LRCHAIN_MODEL_CXX", program.c_str(), 1); }
  ~ModelCompiler() { ::unsetenv("LRCHAIN_MODEL_CXX"); }
};

// A fake compiler: answers --version, and otherwise starts a long-lived grandchild (sleep 300, as
// g++ starts cc1plus), writes its pid to `pid_file` and waits for it; touches `marker` when run.
fs::path fake_compiler(const fs::path& dir, const fs::path& pid_file, const fs::path& marker) {
  const fs::path script = dir / "fake-cxx.sh";
  std::ofstream(script) << "#!/bin/sh\n"
                           "if [ \"$1\" = --version ]; then echo 'fake-cxx 1'; exit 0; fi\n"
                           "touch " << marker.string() << "\n"
                           "sleep 300 &\n"
                           "echo $! > " << pid_file.string() << ".tmp\n"
                           "mv " << pid_file.string() << ".tmp " << pid_file.string() << "\n"
                           "wait\n";
  fs::permissions(script, fs::perms::owner_all);
  return script;
}

// Files of the model cache (none when it does not exist).
std::vector<std::string> cache_files(const fs::path& cache) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(cache, ec), end; !ec && it != end; it.increment(ec)) names.push_back(it->path().filename());
  return names;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST_CASE("model compile: a stop flag set while the compiler runs kills its process group and caches nothing" *
          doctest::timeout(120)) {
  Scratch scratch;
  std::ofstream(scratch.dir / "morse.toml") << morse_model();
  const fs::path pid_file = scratch.dir / "cc1plus.pid", marker = scratch.dir / "compiler-ran";
  const ModelCompiler compiler(fake_compiler(scratch.dir, pid_file, marker).string());
  std::atomic<bool> stop{false};
  pid_t grandchild = 0;
  std::thread stopper([&] {
    grandchild = wait_for_pid_file(pid_file, 60);
    stop = true;
  });
  const auto t0 = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "morse.toml", nullptr, &stop),
                       doctest::Contains("stopped while compiling the model of"), Interrupted);
  stopper.join();
  REQUIRE(grandchild > 0);
  CHECK(seconds_since(t0) < 60);
  CHECK(process_gone(grandchild));  // before: the compiler's child kept running
  CHECK(cache_files(scratch.cache()).empty());
}

TEST_CASE("model compile: a stop flag ends the derivation between its steps, nothing compiled or cached") {
  Scratch scratch;
  std::ofstream(scratch.dir / "morse.toml") << morse_model();
  const fs::path marker = scratch.dir / "compiler-ran";
  const ModelCompiler compiler(fake_compiler(scratch.dir, scratch.dir / "pid", marker).string());
  const std::atomic<bool> stop{true};
  CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "morse.toml", nullptr, &stop),
                       doctest::Contains("stopped while deriving model file"), Interrupted);
  CHECK_FALSE(fs::exists(marker));
  CHECK(cache_files(scratch.cache()).empty());
  // The derivation itself: DerivationStopped, not an InputError blaming the file.
  const derivation::Symbols symbols;
  derivation::ModelFile file = derivation::parse_model_text(morse_model(), "morse.toml");
  const auto values = derivation::parameter_values(file, {});
  const derivation::DerivationStopScope scope(&stop);
  CHECK_THROWS_AS(derivation::derive_model(std::move(file), values, symbols), derivation::DerivationStopped);
}

TEST_CASE("model compile: a failing compiler is one line with its exit status and the end of its stderr") {
  Scratch scratch;
  std::ofstream(scratch.dir / "morse.toml") << morse_model();
  {
    // Before: "compiling the evaluators of ... failed: " and nothing more, exit 1.
    const ModelCompiler compiler("/bin/false");
    CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "morse.toml"),
                         doctest::Contains((std::string("LRCHAIN_MODEL_CXX: the C++ compiler /bin/false failed compiling the model "
                                           "of ") + (scratch.dir / "morse.toml").string() +
                                           " (exit status 1; it wrote nothing on stderr)")
                                               .c_str()),
                         InputError);
  }
  const fs::path script = scratch.dir / "noisy-cxx.sh";
  std::ofstream(script) << "#!/bin/sh\nif [ \"$1\" = --version ]; then echo noisy; exit 0; fi\n"
                           "echo 'first line' >&2\necho 'x.cpp:1: error: the last line' >&2\nexit 4\n";
  fs::permissions(script, fs::perms::owner_all);
  const ModelCompiler compiler(script.string());
  try {
    compile_model_file(scratch.dir / "morse.toml");
    FAIL("compiled");
  } catch (const InputError& e) {
    const std::string message = e.what();
    CHECK(message.find("(exit status 4; stderr ends: first line x.cpp:1: error: the last line)") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
  }
  for (const auto& name : cache_files(scratch.cache())) CHECK(name.find(".so") == std::string::npos);
}

TEST_CASE("model cache: a directory at the entry's manifest is refused before the compiler runs" * doctest::timeout(600)) {
  if (!model_compiler_available()) return;
  Scratch scratch;
  std::ofstream(scratch.dir / "morse.toml") << morse_model();
  CompiledModelInfo info;
  compile_model_file(scratch.dir / "morse.toml", &info);
  fs::path manifest = info.library;
  manifest.replace_extension("").replace_extension(".manifest");
  fs::remove(manifest);
  fs::remove(info.library);
  fs::create_directory(manifest);
  // Before: exit 2 only after compiling, with the fresh object left behind.
  CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "morse.toml"),
                       doctest::Contains(("the model cache entry " + manifest.string() + " is not a regular file; delete it").c_str()),
                       InputError);
  for (const auto& name : cache_files(scratch.cache())) CHECK(name.find(".so") == std::string::npos);
  // A replaced entry leaves one object: the one its manifest names.
  fs::remove(manifest);
  compile_model_file(scratch.dir / "morse.toml", &info);
  std::ofstream(manifest, std::ios::trunc) << std::string(64, 'e') << "\n";  // names an object that is not there
  compile_model_file(scratch.dir / "morse.toml", &info);
  int objects = 0;
  for (const auto& name : cache_files(scratch.cache())) objects += name.find(".so") != std::string::npos;
  CHECK(objects == 1);
}

TEST_CASE("model coefficients: a parameter value that leaves no frequency is blamed, not theta" * doctest::timeout(600)) {
  Scratch scratch;
  std::ofstream(scratch.dir / "morse.toml") << morse_model();
  const auto definition = compile_model_file(scratch.dir / "morse.toml");
  const Index acoustic = Model(definition).branch("acoustic");
  // omega^2 = 2 a^2 b D1 (linearised Morse force 2 a^2 b r) underflows to 0 at a = 1e-300.
  const Model tiny(definition, {{"a", 1e-300}});
  try {
    coefficients(tiny, acoustic, 1.0);
    FAIL("evaluated");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "a");  // before: "invalid theta"
    CHECK(std::string(e.what()).find("at its default 1 the coefficients exist there") != std::string::npos);
  }
  // a = 1e-100: omega = sqrt(2 * 4 sin^2(1/2)) * 1e-100 (no underflow), the acoustic dispersion.
  CHECK(coefficients(Model(definition, {{"a", 1e-100}}), acoustic, 1.0).omega ==
        doctest::Approx(std::sqrt(2.0 * 4 * std::sin(0.5) * std::sin(0.5)) * 1e-100).epsilon(1e-12));
  // theta = 0 on the acoustic branch is theta's own fault, at any parameter values.
  try {
    coefficients(Model(definition, {{"b", 2.0}}), acoustic, 0.0);
    FAIL("evaluated");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "theta");
  }
}

TEST_CASE("lrchain derive and coeffs --model stop on SIGINT/SIGTERM with 130/143 and one line" * doctest::timeout(300)) {
  Scratch scratch;
  const fs::path pid_file = scratch.dir / "cc1plus.pid", marker = scratch.dir / "compiler-ran";
  const std::string fake = fake_compiler(scratch.dir, pid_file, marker).string();
  std::ofstream(scratch.dir / "morse.toml") << morse_model();
  // coeffs compiles: SIGTERM while the (fake) compiler runs.
  {
    ProcessOptions o;
    o.capture_stderr = true;
    o.capture_stdout = true;
    o.environment = {"LRCHAIN_MODEL_CXX=" + fake, "XDG_CACHE_HOME=" + (scratch.dir / "cache").string()};
    ChildProcess lrchain({LRCHAIN_CLI, "coeffs", "--model", (scratch.dir / "morse.toml").string(), "--branch", "acoustic",
                          "--theta", "1"},
                         o);
    const pid_t grandchild = wait_for_pid_file(pid_file, 60);
    REQUIRE(grandchild > 0);
    const auto t0 = std::chrono::steady_clock::now();
    lrchain.send_signal(SIGTERM);
    const ProcessResult r = lrchain.wait();
    CHECK(seconds_since(t0) < 2);
    CHECK(r.exited);
    CHECK(r.exit_code == 143);
    CHECK(r.output.empty());
    CHECK(r.error_output.find("interrupted by SIGTERM: stopped while compiling the model of") != std::string::npos);
    CHECK(r.error_output.find('\n') == r.error_output.size() - 1);
    CHECK(process_gone(grandchild));  // before: cc1plus (here: sleep) kept running
    CHECK(cache_files(scratch.cache()).empty());
  }
  // derive: SIGINT during a derivation of several seconds (16 s on an idle 2-core machine).
  {
    std::ofstream(scratch.dir / "slow.toml") << slow_three_field_model();
    ProcessOptions o;
    o.capture_stderr = true;
    o.capture_stdout = true;
    const auto t0 = std::chrono::steady_clock::now();
    ChildProcess lrchain({LRCHAIN_CLI, "derive", "--model", (scratch.dir / "slow.toml").string()}, o);
    ::usleep(700000);
    const auto t1 = std::chrono::steady_clock::now();
    lrchain.send_signal(SIGINT);
    const ProcessResult r = lrchain.wait();
    MESSAGE("derive stopped " << seconds_since(t1) << " s after SIGINT (" << seconds_since(t0) << " s in all)");
    CHECK(seconds_since(t1) < 2);
    CHECK(r.exited);
    CHECK(r.exit_code == 130);
    CHECK(r.output.empty());
    CHECK(r.error_output == "lrchain: interrupted by SIGINT while deriving " + (scratch.dir / "slow.toml").string() + "\n");
  }
}

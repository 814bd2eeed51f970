// `lrchain sweep` treats what it reads as data and never loses or fakes a result (issue 25):
// a sweep's name and output never run as gnuplot commands, names with control characters are
// refused, a damaged or truncated results file is refused when resuming (per-point SHA-256), a
// user's file next to the results is never replaced, and a sweep too large for memory is refused
// before its axes' values are generated. Each case failed on f4efd39: the name's system() ran, the
// garbage value 2.2e35 was resumed as a result, a truncated file gave exit 1, the user's CSV and
// script were overwritten, and count = 1e9 allocated 8 GB before any check.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/process.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "../support/run_lrchain.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain::jobs::sweep;

namespace {

fs::path scratch(const std::string& name) { return lrchain::test::sweep_scratch("sweep-safety", name); }
void write(const fs::path& f, const std::string& text) { lrchain::test::write_text(f, text); }

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const char* const base_config = lrchain::test::short_bright_base;

// A 2 x 2 grid over theta and a decade of detunings with a figure of max_Ex; `name_line` and the
// output as given.
std::string figure_sweep(const std::string& name_line, const std::string& output) {
  return "job = \"bright\"\n" + name_line + "\nbase = \"base.toml\"\noutput = \"" + output +
         "\"\nfigure = \"max_Ex\"\n[[axis]]\nparameter = \"bright.theta\"\nvalues = [1.4, 1.6]\n"
         "[[axis]]\nparameter = \"bright.detuning\"\nvalues = [-1e-4, -1e-3]\n";
}

// theta = 1.5, 2.5, 2.5, 1.7, 2.5 at rho = 1/3: statuses ok, invalid, invalid, ok, invalid (2.5 is
// outside the optical focusing interval, docs/regime-maps.md): the bytes 01 04 04 01 04 in /status.
std::string list_sweep(const std::string& output) {
  return "job = \"bright\"\nbase = \"base.toml\"\noutput = \"" + output +
         "\"\nlayout = \"list\"\n[[axis]]\nparameter = \"bright.theta\"\nvalues = [1.5, 2.5, 2.5, 1.7, 2.5]\n";
}

// Replaces the one occurrence of `from` in the file by `to` (same length); false if not exactly one.
bool patch_once(const fs::path& file, const std::string& from, const std::string& to) {
  std::string bytes = slurp(file);
  const auto at = bytes.find(from);
  if (at == std::string::npos || bytes.find(from, at + 1) != std::string::npos) return false;
  bytes.replace(at, from.size(), to);
  write(file, bytes);
  return true;
}

std::string double_bytes(double v) {
  std::string s(sizeof v, '\0');
  std::memcpy(s.data(), &v, sizeof v);
  return s;
}

}  // namespace

TEST_CASE("sweep safety: a hostile name never runs in gnuplot, neither during the sweep nor when the script is re-run") {
  const fs::path d = scratch("gnuplot");
  write(d / "base.toml", base_config);
  // The name closes gnuplot's quote and calls system().
  write(d / "s.toml", figure_sweep(R"(name = "x'; system('touch PWNED1'); print '")", "out/r.h5"));
  const auto r = lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet", "--json"}, d);
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::string script = slurp(d / "out" / "r_max_Ex.gp");
  const std::string apostrophe = "\xE2\x80\x99";  // U+2019, how a quote is shown (gnuplot_text.hpp)
  CHECK(script.find("set title 'x" + apostrophe + "; system(" + apostrophe + "touch PWNED1" + apostrophe + "); print " + apostrophe +
                    ": log10(max_Ex)") != std::string::npos);
  CHECK(script.find("plot './r_max_Ex.dat'") != std::string::npos);
  if (lrchain::program_in_path("gnuplot")) {
    CHECK(fs::exists(d / "out" / "r_max_Ex.png"));  // the figure is drawn all the same
    lrchain::ProcessOptions o;
    o.working_directory = d / "out";
    o.capture_stderr = true;
    CHECK(lrchain::run_program({"gnuplot", "r_max_Ex.gp"}, o).ok());
  }
  for (const fs::path& where : {d, d / "out"})
    CHECK(!fs::exists(where / "PWNED1"));
  fs::remove_all(d);
}

TEST_CASE("sweep safety: a control character in the name, the output or --output is refused before anything runs") {
  const fs::path d = scratch("control");
  write(d / "base.toml", base_config);
  struct Case {
    std::string sweep;
    std::vector<std::string> extra;
    std::string expected;
  };
  const Case cases[] = {
      {figure_sweep(R"(name = "a\nset output '|touch PWNED'")", "out/r.h5"), {}, "'name' in the top level at s.toml:2: contains a control character (byte 0x0a)"},
      {figure_sweep(R"(name = "a\u0000b")", "out/r.h5"), {}, "'name' in the top level at s.toml:2: contains a control character (byte 0x00)"},
      {figure_sweep(R"(name = "a\u0085b")", "out/r.h5"), {}, "'name' in the top level at s.toml:2: contains a control character (U+0085)"},
      {figure_sweep("", "out/r\\r.h5"), {}, "'output' in the top level at s.toml:4: contains a control character (byte 0x0d)"},
      {figure_sweep("", "out/r'.h5"), {}, "'output' in the top level at s.toml:4: the figure's files are named after it"},
      // gnuplot reads a file argument or `plot '<cmd'` starting with '<' as a shell command.
      {figure_sweep("", "out/<touch PWNED.h5"), {}, "'output' in the top level at s.toml:4: the figure's files are named after it"},
      {figure_sweep("", "out/r.h5"), {"--output", "out/a\nb.h5"}, "invalid --output: contains a control character (byte 0x0a)"},
  };
  for (const auto& k : cases) {
    CAPTURE(k.sweep);
    write(d / "s.toml", k.sweep);
    std::vector<std::string> args{"sweep", "--config", "s.toml", "--quiet"};
    args.insert(args.end(), k.extra.begin(), k.extra.end());
    const auto r = lrchain::test::run_lrchain(args, d);
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(r.err.find(k.expected) != std::string::npos, r.err);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(d / "out"));
    CHECK(!fs::exists(d / "PWNED"));
  }
  fs::remove_all(d);
}

TEST_CASE("sweep safety: a resumed sweep refuses a damaged record, an unknown status code and a truncated file (exit 2)") {
  const fs::path d = scratch("checksum");
  write(d / "base.toml", base_config);
  write(d / "s.toml", figure_sweep("", "r.h5"));
  REQUIRE(lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet"}, d).exit_code == 0);
  const fs::path h5 = d / "r.h5";
  const std::string pristine = slurp(h5);
  const SweepConfig c = load_sweep_config(d / "s.toml");
  const SweepResults good = read_results(h5, c, make_job(c));
  // Resuming the intact file runs nothing and keeps every result.
  const auto again = lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet", "--json"}, d);
  REQUIRE_MESSAGE(again.exit_code == 0, again.err);
  CHECK(nlohmann::json::parse(again.out)["ran"] == 0);

  // Garbage in one value: final_Ey of point 1 (theta = 1.4, detuning = -1e-3) becomes 2.2e35.
  const auto names = good.scalar_names;
  const std::size_t final_Ey = std::size_t(std::find(names.begin(), names.end(), "final_Ey") - names.begin());
  write(h5, pristine);
  REQUIRE(patch_once(h5, double_bytes(good.scalars[final_Ey * good.points + 1]), double_bytes(2.2e35)));
  const auto before = fs::last_write_time(h5);
  auto r = lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet"}, d);
  CHECK(r.exit_code == 2);
  CHECK_MESSAGE(r.err.find("'r.h5' is damaged: point 1 (bright.theta = 1.4, bright.detuning = -0.001) does not match its SHA-256 checksum") !=
                    std::string::npos,
                r.err);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(fs::last_write_time(h5) == before);  // the file is left as it was

  // A truncated file.
  write(h5, pristine.substr(0, pristine.size() / 2));
  r = lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet"}, d);
  CHECK(r.exit_code == 2);
  CHECK_MESSAGE(r.err.find("'r.h5' is truncated or damaged") != std::string::npos, r.err);

  // An unknown status code: the list sweep's statuses 01 04 04 01 04, the second one set to 9.
  write(d / "l.toml", list_sweep("l.h5"));
  REQUIRE(lrchain::test::run_lrchain({"sweep", "--config", "l.toml", "--quiet"}, d).exit_code == 0);
  REQUIRE(patch_once(d / "l.h5", std::string("\x01\x04\x04\x01\x04", 5), std::string("\x01\x09\x04\x01\x04", 5)));
  r = lrchain::test::run_lrchain({"sweep", "--config", "l.toml", "--quiet"}, d);
  CHECK(r.exit_code == 2);
  CHECK_MESSAGE(r.err.find("'l.h5' is damaged: point 1 (bright.theta = 2.5) has status code 9") != std::string::npos, r.err);
  fs::remove_all(d);
}

TEST_CASE("sweep safety: a user's CSV or figure file next to the results is refused before any point runs") {
  const fs::path d = scratch("side-files");
  write(d / "base.toml", base_config);
  write(d / "s.toml", figure_sweep("", "out/r.h5"));
  fs::create_directories(d / "out");
  for (const char* users : {"r.csv", "r_max_Ex.dat", "r_max_Ex.gp", "r_max_Ex_exponent.csv"}) {
    CAPTURE(users);
    write(d / "out" / users, "the user's own data\n");
    const auto r = lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet"}, d);
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(r.err.find(std::string("'out/") + users + "' exists and was not written by this sweep") != std::string::npos, r.err);
    CHECK(!fs::exists(d / "out" / "r.h5"));  // no point ran
    CHECK(slurp(d / "out" / users) == "the user's own data\n");
    fs::remove(d / "out" / users);
  }
  // The sweep's own files are rewritten when it runs again; one the user changed since is not.
  REQUIRE(lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet"}, d).exit_code == 0);
  CHECK(lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet"}, d).exit_code == 0);
  write(d / "out" / "r_max_Ex.gp", slurp(d / "out" / "r_max_Ex.gp") + "set grid\n");
  const auto r = lrchain::test::run_lrchain({"sweep", "--config", "s.toml", "--quiet"}, d);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("'out/r_max_Ex.gp' exists and was not written by this sweep (it changed since)") != std::string::npos);
  CHECK(slurp(d / "out" / "r_max_Ex.gp").ends_with("set grid\n"));
  fs::remove_all(d);
}

TEST_CASE("sweep safety: an axis of 1e9 values is refused from its count, before its values take 8 GB") {
  const fs::path d = scratch("memory");
  write(d / "base.toml", base_config);
  write(d / "s.toml", "job = \"bright\"\nbase = \"base.toml\"\noutput = \"out/r.h5\"\n[[axis]]\nparameter = \"bright.theta\"\n"
                      "from = 1.2\nto = 1.8\ncount = 1000000000\n");
  // Under a 1 GiB address space: generating the values first (8 GB) ended in bad_alloc (exit 1).
  // 1e9 points x about 300 bytes each is far above any machine's memory.
  REQUIRE_MESSAGE(lrchain::program_in_path("prlimit"), "prlimit (util-linux) is needed by this test");
  // The sanitizer build cannot start under an RLIMIT_AS (AddressSanitizer's shadow memory); there,
  // an 8 GB allocation is refused by AddressSanitizer's own allocator limit and fails the test.
#ifdef LRCHAIN_SANITIZE_BUILD
  const std::vector<std::string> limited{LRCHAIN_CLI, "sweep", "--config", "s.toml", "--quiet"};
#else
  const std::vector<std::string> limited{"prlimit", "--as=1073741824", LRCHAIN_CLI, "sweep", "--config", "s.toml", "--quiet"};
#endif
  const auto start = std::chrono::steady_clock::now();
  const auto r = lrchain::test::run_command(limited, d);
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 20);
  CHECK(r.exit_code == 2);
  CHECK_MESSAGE(r.err.find("'count' in [[axis]] at s.toml:8: the sweep's 1e+09 points need about") != std::string::npos, r.err);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(!fs::exists(d / "out"));
  // Two axes whose grid exceeds 1e9 points: refused from the counts alone.
  write(d / "s.toml", "job = \"bright\"\nbase = \"base.toml\"\noutput = \"out/r.h5\"\n[[axis]]\nparameter = \"bright.theta\"\n"
                      "from = 1.2\nto = 1.8\ncount = 100000\n[[axis]]\nparameter = \"bright.n0\"\nfrom = 0\nto = 1\ncount = 100000\n");
  const auto grid = lrchain::test::run_command(limited, d);
  CHECK(grid.exit_code == 2);
  CHECK_MESSAGE(grid.err.find("s.toml:13: the grid has more than 1e9 points") != std::string::npos, grid.err);
  fs::remove_all(d);
}

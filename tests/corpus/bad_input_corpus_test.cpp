// The bad-input corpus: every numeric option of every subcommand (from `lrchain --help`), every key
// of examples/*.toml, and every file lrchain reads, each with NaN, inf, -inf, -1, 0, 1e308, 1e300pi,
// an empty string, a word and a wrong type (or a missing, empty, binary, malformed file). Each case
// must exit 2 with one stderr line naming the option, key or file, leave nothing new on disk and end
// within the timeout.
//
// Environment: LRCHAIN_CORPUS_TIMEOUT (seconds per case, default 10), LRCHAIN_CORPUS_JOBS (cases
// at the same time, default 4), LRCHAIN_CORPUS_FILTER (run only cases whose description contains
// this), LRCHAIN_CORPUS_SHARD=K/N (run only the cases whose index is K modulo N: CTest runs the
// corpus as N entries in parallel), LRCHAIN_CORPUS_REPORT (also write the failures grouped by rule to this file),
// LRCHAIN_CORPUS_KEEP=1 (keep the case directories), LRCHAIN_CORPUS_MEMORY_MB (address-space cap
// of each case, default 3000).
#include <doctest/doctest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

#include "case_runner.hpp"
#include "corpus_case.hpp"
#include "help_discovery.hpp"

namespace {

using namespace lrchain::corpus;

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

std::string escaped(const std::string& s, std::size_t max = 300) {
  std::string o;
  for (char c : s.substr(0, max)) o += c == '\n' ? std::string("\\n") : std::string(1, c);
  return s.size() > max ? o + "..." : o;
}

// Caps the memory of every case: a value that is wrongly accepted must not take the machine's memory
// (children inherit the limit; under AddressSanitizer, whose shadow memory needs a large address
// space, its own RSS limit does the job).
void limit_case_memory(RunSettings& s) {
  const long mb = std::stol(env_or("LRCHAIN_CORPUS_MEMORY_MB", "3000"));
#if defined(__SANITIZE_ADDRESS__)
  const std::string asan = env_or("ASAN_OPTIONS", "");
  s.environment.push_back("ASAN_OPTIONS=" + asan + (asan.empty() ? "" : ":") + "hard_rss_limit_mb=" + std::to_string(mb));
#else
  (void)s;
  const rlim_t bytes = static_cast<rlim_t>(mb) << 20;
  rlimit r{bytes, bytes};
  ::setrlimit(RLIMIT_AS, &r);
#endif
}

// "K/N" -> (K, N) with 0 <= K < N: the cases this process runs are those with index K modulo N.
std::pair<std::size_t, std::size_t> shard_of(const std::string& text) {
  const auto slash = text.find('/');
  const std::size_t k = std::stoul(text.substr(0, slash)), n = slash == std::string::npos ? 1 : std::stoul(text.substr(slash + 1));
  if (n == 0 || k >= n) throw std::invalid_argument("LRCHAIN_CORPUS_SHARD must be K/N with 0 <= K < N, got " + text);
  return {k, n};
}

std::string failure_line(const CorpusCase& c, const CaseOutcome& o) {
  std::ostringstream s;
  s << "FAIL [" << c.category << "] " << c.description << " | $ " << o.command_line << " | "
    << (o.exit_code >= 0 ? "exit " + std::to_string(o.exit_code) : "signal " + std::to_string(o.signal_number))
    << " in " << static_cast<int>(o.seconds * 1000) << " ms | stderr: \"" << escaped(o.error_output) << "\" | broken:";
  for (const auto& b : o.broken) s << " [" << b.rule << "] " << b.detail << ";";
  return s.str();
}

}  // namespace

TEST_CASE("bad-input corpus: every bad option value, config key and file exits 2, says one line, writes nothing") {
  RunSettings settings;
  settings.lrchain = LRCHAIN_CLI;
  settings.timeout = std::chrono::milliseconds(static_cast<long>(1000 * std::stod(env_or("LRCHAIN_CORPUS_TIMEOUT", "10"))));
  settings.keep_directories = env_or("LRCHAIN_CORPUS_KEEP", "0") == "1";
  settings.environment = {"OMP_NUM_THREADS=1", "LC_ALL=C"};
  std::string scratch = (std::filesystem::temp_directory_path() / "lrchain-corpus-XXXXXX").string();
  REQUIRE(::mkdtemp(scratch.data()) != nullptr);
  settings.scratch = scratch;
  limit_case_memory(settings);

  const auto commands = discover_commands(settings.lrchain);
  Corpus corpus;
  add_option_cases(commands, corpus);
  add_config_cases(std::filesystem::path(LRCHAIN_SOURCE_DIR) / "examples", commands, corpus);
  add_file_cases(commands, corpus);
  add_sweep_config_cases(std::filesystem::path(LRCHAIN_SOURCE_DIR) / "tests" / "corpus", corpus);
  add_model_file_cases(corpus);
  for (const auto& e : corpus.errors) std::cout << "corpus generation: " << e << "\n";
  CHECK(corpus.errors.empty());

  std::map<std::string, int> generated;
  for (const auto& c : corpus.cases) ++generated[c.category];
  std::cout << "generated from " << commands.size() << " help texts and examples/*.toml:";
  for (const auto& [category, n] : generated) std::cout << " " << category << " " << n << ";";
  std::cout << "\n";

  const std::string filter = env_or("LRCHAIN_CORPUS_FILTER", "");
  const auto [shard, shards] = shard_of(env_or("LRCHAIN_CORPUS_SHARD", "0/1"));
  std::vector<const CorpusCase*> selected;
  for (std::size_t i = 0; i < corpus.cases.size(); ++i)
    if (i % shards == shard && (filter.empty() || corpus.cases[i].description.find(filter) != std::string::npos))
      selected.push_back(&corpus.cases[i]);
  std::size_t generated_bad = 0;
  for (const auto& c : corpus.cases) generated_bad += c.control ? 0 : 1;

  std::vector<CaseOutcome> outcomes(selected.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> workers;
  const int jobs = std::max(1, std::stoi(env_or("LRCHAIN_CORPUS_JOBS", "4")));
  const auto t0 = std::chrono::steady_clock::now();
  for (int j = 0; j < jobs; ++j)
    workers.emplace_back([&] {
      for (std::size_t i; (i = next++) < selected.size();) outcomes[i] = run_case(*selected[i], settings);
    });
  for (auto& w : workers) w.join();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::filesystem::remove_all(scratch);

  // Counts per category, failures one block each, then the failures grouped by the rule they broke.
  std::map<std::string, std::pair<int, int>> per_category;  // cases, failures
  std::map<std::string, std::vector<std::string>> by_rule;
  std::map<std::string, int> per_value;  // option and config values by corpus value
  std::size_t bad_cases = 0, failures = 0, control_failures = 0;
  double slowest = 0;
  std::ostringstream failure_text;
  for (std::size_t i = 0; i < selected.size(); ++i) {
    const CorpusCase& c = *selected[i];
    const CaseOutcome& o = outcomes[i];
    auto& [n, f] = per_category[c.category];
    ++n;
    if (!c.value.empty()) ++per_value[c.value];
    bad_cases += c.control ? 0 : 1;
    slowest = std::max(slowest, o.seconds);
    if (o.broken.empty()) continue;
    ++f;
    (c.control ? control_failures : failures) += 1;
    failure_text << failure_line(c, o) << "\n";
    // Grouped by the first rule broken (a wrong exit code also breaks the stderr rules).
    const BrokenRule& first = o.broken.front();
    by_rule[c.category + " / " +
            (first.rule == "exit code" || first.rule == "killed by a signal" ? first.rule + ": " + first.detail
                                                                             : first.rule)].push_back("[" + c.category + "] " + c.description + "  ->  " +
                                                     escaped(o.error_output, 160));
  }
  std::ostringstream summary;
  summary << "bad-input corpus: " << generated_bad << " cases generated; shard " << shard << "/" << shards
          << ": " << bad_cases << " cases that must fail + " << per_category["control"].first << " controls, run in " << static_cast<int>(wall) << " s with "
          << jobs << " jobs (slowest case " << static_cast<int>(slowest * 1000) << " ms, timeout "
          << settings.timeout.count() / 1000.0 << " s)\n";
  for (const auto& [category, nf] : per_category)
    summary << "  " << category << ": " << nf.first << " cases, " << nf.second << " failed\n";
  summary << "  by value:";
  for (const auto& [value, n] : per_value) summary << " " << value << " " << n << ";";
  summary << "\n";
  for (const auto& [category, n] : corpus.skipped_as_valid)
    summary << "  (" << category << ": " << n << " values inside the option's valid range, not run)\n";
  std::cout << failure_text.str() << summary.str();
  if (!by_rule.empty()) {
    std::cout << "failures by the first rule broken:\n";
    for (const auto& [rule, list] : by_rule) std::cout << "  " << rule << ": " << list.size() << "\n";
  }
  if (const std::string report = env_or("LRCHAIN_CORPUS_REPORT", ""); !report.empty()) {
    std::ofstream r(report);
    r << summary.str() << "\n";
    for (const auto& [rule, list] : by_rule) {
      r << "== " << rule << ": " << list.size() << " cases\n";
      for (const auto& l : list) r << "  " << l << "\n";
    }
    r << "\n== every failure\n" << failure_text.str();
  }
  CHECK(generated_bad >= 300);
  CHECK(control_failures == 0);
  CHECK(failures == 0);
}

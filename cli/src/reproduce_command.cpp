// `lrchain reproduce`: runs every computation of the paper (coefficients, regimes, lattice
// experiments, dark breathers) and writes a static HTML report, DIR/index.html (issue 6).
#include <omp.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "figure_format_option.hpp"
#include "help_text.hpp"
#include "options.hpp"
#include "shipped_data.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/output_lock.hpp"
#include "report/html_report.hpp"
#include "report/lrchain_process.hpp"
#include "report/published_paths.hpp"
#include "report/steps.hpp"


namespace lrchain::cli {

namespace {

namespace fs = std::filesystem;
using namespace lrchain::report;

struct ReproduceArgs {
  bool quick = false, full = false, list = false, progress_json = false;
  std::string out = "lrchain-report";
  std::string examples, errata;
  int jobs = 0;
  std::vector<std::string> only;
};

// First existing path among: the option, <rel> in the shipped data (<prefix>/share/lrchain, or the
// source tree of a build tree's lrchain); a given path must be a directory (`directory`) or a
// regular file (otherwise).
fs::path locate(const std::string& given, const std::string& rel, const std::string& option, bool directory) {
  if (!given.empty()) {
    if (!fs::exists(given)) throw InvalidParameter(option, "'" + given + "' does not exist");
    if (directory && !fs::is_directory(given))
      throw InvalidParameter(option, "'" + given + "' is not a directory");
    if (!directory && !fs::is_regular_file(given))
      throw InvalidParameter(option, "'" + given + "' is not a regular file");
    return fs::absolute(given);
  }
  for (const fs::path& root : shipped_data_roots())  // shipped_data.hpp
    if (fs::exists(root / rel)) return root / rel;
  throw InvalidParameter(option, "cannot find " + rel + " (give " + option + ")");
}

// A report directory is recognised by this marker file, which reproduce writes first; DIR and
// DIR.partial are removed only when they carry it.
constexpr const char* report_marker = ".lrchain-report";
constexpr const char* marker_text = "lrchain report\nversion " LRCHAIN_VERSION_STRING "\n";

bool has_report_marker(const fs::path& dir) {
  std::ifstream in(dir / report_marker);
  std::string first;
  return fs::is_regular_file(dir / report_marker) && std::getline(in, first) && first == "lrchain report";
}

// Empty, or holding only a lock file left by a run that was killed.
bool holds_nothing(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename() != ".lrchain-lock") return false;
  return true;
}

// Absolute path with symbolic links resolved where they exist, without a trailing separator.
fs::path resolved(const fs::path& p) {
  fs::path r = fs::weakly_canonical(fs::absolute(p));
  if (r.filename().empty() && r.has_parent_path() && r != r.root_path()) r = r.parent_path();
  return r;
}

// True when `dir` is `inside` or one of its ancestors.
bool contains(const fs::path& dir, const fs::path& inside) {
  auto d = dir.begin(), i = inside.begin();
  for (; d != dir.end(); ++d, ++i)
    if (i == inside.end() || *d != *i) return false;
  return true;
}

// Refuses (exit 2, before anything is written) an --out that would delete what lrchain did not
// write: the current directory or a parent of it, a non-empty directory that is not a report,
// a DIR.partial that reproduce did not create.
void check_out_dir(const fs::path& out, const fs::path& partial) {
  const fs::path cwd = resolved(fs::current_path());
  for (const fs::path& dir : {out, partial})
    if (contains(resolved(dir), cwd))
      throw InvalidParameter("out", "'" + dir.string() + "' is the current directory or contains it; give a "
                                    "new directory for the report");
  if (fs::exists(out)) {
    if (!fs::is_directory(out)) throw InvalidParameter("out", "'" + out.string() + "' exists and is not a directory");
    if (!fs::is_empty(out) && !has_report_marker(out))
      throw InvalidParameter("out", "'" + out.string() + "' is not empty and is not an lrchain report (no " +
                                        report_marker + " file); give a new or empty directory");
  }
  if (fs::exists(partial)) {
    if (!fs::is_directory(partial) || !(holds_nothing(partial) || has_report_marker(partial)))
      throw InvalidParameter("out", "'" + partial.string() + "' exists and was not written by lrchain reproduce; "
                                    "move it away or give another --out");
  }
}

// Empties the locked DIR.partial of an earlier, unfinished report (it carries the marker).
void clear_partial(const fs::path& partial) {
  for (const auto& entry : fs::directory_iterator(partial))
    if (entry.path().filename() != ".lrchain-lock") fs::remove_all(entry.path());
}

// One line of --progress-json on stderr: the JSON object `event` on a line of its own, flushed.
void progress_line(const nlohmann::json& event) {
  std::fprintf(stderr, "%s\n", event.dump().c_str());
  std::fflush(stderr);
}

void run_reproduce(const ReproduceArgs& a) {
  std::vector<Step> steps = all_steps();
  if (a.list) {
    for (const auto& s : steps) std::printf("%-20s %s\n", s.id.c_str(), s.title.c_str());
    return;
  }
  if (!a.only.empty()) {
    std::vector<Step> chosen;
    for (const auto& id : a.only) {
      auto it = std::find_if(steps.begin(), steps.end(), [&](const Step& s) { return s.id == id; });
      if (it == steps.end()) throw InvalidParameter("only", "unknown step '" + id + "' (see --list)");
      chosen.push_back(*it);
    }
    steps = chosen;
  }
  if (a.jobs < 0 || a.jobs > 64) throw InvalidParameter("jobs", "must be in [1, 64] (0: one per core)");
  const fs::path out = fs::absolute(a.out).lexically_normal();
  if (out.filename().empty() || out == out.root_path())
    throw InvalidParameter("out", "'" + a.out + "' names no directory of its own; give a new directory");
  const fs::path partial = out.string() + ".partial";
  check_out_dir(out, partial);

  StepContext ctx;
  ctx.exe = current_executable();
  ctx.examples = locate(a.examples, "examples", "examples", true);
  ctx.full = a.full;
  const int jobs = a.jobs > 0 ? a.jobs : std::max(1, omp_get_num_procs());
  ctx.child_threads = std::max(1, omp_get_num_procs() / jobs);
  ReportInfo info;
  info.mode = a.full ? "full" : "quick";
  info.provenance = current_provenance();
  try {
    const fs::path errata = locate(a.errata, "docs/paper-errata.md", "errata", false);
    std::ifstream in(errata);
    std::stringstream text;
    text << in.rdbuf();
    info.errata_markdown = text.str();
  } catch (const InvalidParameter&) {
    if (!a.errata.empty()) throw;
  }

  ctx.out = partial;
  jobs::OutputLock lock(partial);  // refuses a second reproduce into the same --out
  clear_partial(partial);
  jobs::write_file_atomic(partial, report_marker, marker_text);
  forward_interrupts_to_children();

  // Long steps first so that the two cores stay busy; the report keeps the paper's order.
  std::vector<std::size_t> order(steps.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](auto x, auto y) { return steps[x].cost > steps[y].cost; });

  std::vector<Section> sections(steps.size());
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  int done = 0;
  if (a.progress_json)
    progress_line({{"event", "start"}, {"mode", info.mode}, {"steps", steps.size()}, {"jobs", jobs}, {"out", ctx.out.string()}});
  else
    std::fprintf(stderr, "lrchain reproduce --%s: %zu steps, %d at a time, writing %s\n", info.mode.c_str(),
                 steps.size(), jobs, ctx.out.c_str());
#pragma omp parallel for schedule(dynamic, 1) num_threads(jobs)
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Step& step = steps[order[k]];
    const auto s0 = std::chrono::steady_clock::now();
    if (a.progress_json) {
#pragma omp critical(reproduce_progress)
      progress_line({{"event", "step_started"}, {"step", step.id}, {"title", step.title}, {"seconds", elapsed()}});
    }
    Section section;
    try {
      if (interrupt_signal() != 0) throw std::runtime_error("not run (interrupted)");
      section = step.run(ctx);
    } catch (const std::exception& e) {
      section.failed = true;
      section.error = e.what();
    }
    if (section.id.empty()) section.id = step.id;
    if (section.title.empty()) section.title = step.title;
    section.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
    const Counts c = count({section});
#pragma omp critical(reproduce_progress)
    {
      ++done;
      if (a.progress_json)
        progress_line({{"event", "step_finished"}, {"step", step.id}, {"done", done}, {"steps", steps.size()},
                       {"seconds", elapsed()}, {"step_seconds", section.seconds}, {"failed", section.failed},
                       {"error", section.failed ? nlohmann::json(section.error) : nlohmann::json()}, {"pass", c.pass},
                       {"deviates", c.deviates}, {"erratum", c.erratum}, {"unresolved", c.unresolved}});
      else
        std::fprintf(stderr, "[%2d/%zu] %6.1f s  %-20s %s in %.1f s: %d pass, %d deviates, %d erratum, %d unresolved%s%s\n",
                     done, steps.size(), elapsed(), step.id.c_str(), section.failed ? "FAILED" : "done", section.seconds,
                     c.pass, c.deviates, c.erratum, c.unresolved, section.failed ? " - " : "",
                     section.failed ? section.error.c_str() : "");
      sections[order[k]] = std::move(section);
    }
  }
  if (const int signal_number = interrupt_signal(); signal_number != 0) {
    // Every child run has ended (each step waits for its own); the unfinished report goes.
    std::error_code ec;
    fs::remove_all(partial, ec);
    throw Interrupted(signal_number, fmt::format("reproduce interrupted by {}: its lrchain runs were stopped and "
                                                 "'{}' removed", signal_number == SIGINT ? "SIGINT" : "SIGTERM",
                                                 partial.string()));
  }
  // The steps name their figures as PNG; with --figure-format they were drawn as SVG or PDF.
  for (auto& section : sections)
    for (auto& figure : section.figures) figure.file = jobs::figure_file_name(figure.file);
  info.total_seconds = elapsed();
  report::point_json_files_at(partial, out);  // the runs' JSON files name DIR, not DIR.partial
  write_html_report(ctx.out, sections, info);
  if (fs::exists(out)) {
    if (!fs::is_empty(out) && !has_report_marker(out))
      throw std::runtime_error("'" + out.string() + "' was filled by something else during the run; the report "
                               "is in '" + partial.string() + "'");
    fs::remove_all(out);
  }
  fs::rename(partial, out);
  lock.moved_to(out);

  const Counts c = count(sections);
  int failed = 0;
  nlohmann::json steps_json = nlohmann::json::array(), missing = nlohmann::json::array();
  for (const auto& s : sections) {
    failed += s.failed;
    for (const auto& f : s.figures)
      if (!fs::exists(out / f.file)) missing.push_back(f.file);
    const Counts sc = count({s});
    steps_json.push_back({{"id", s.id}, {"seconds", s.seconds}, {"failed", s.failed}, {"pass", sc.pass},
                          {"deviates", sc.deviates}, {"erratum", sc.erratum}, {"unresolved", sc.unresolved}});
  }
  const nlohmann::json summary = {{"report", (out / "index.html").string()}, {"mode", info.mode},
                                  {"pass", c.pass}, {"deviates", c.deviates}, {"erratum", c.erratum}, {"unresolved", c.unresolved},
                                  {"failed_steps", failed}, {"figures_missing", missing}, {"seconds", info.total_seconds},
                                  {"steps", steps_json}, {"provenance", provenance_json(info.provenance)}};
  std::printf("%s\n", summary.dump(2).c_str());
  if (a.progress_json)
    progress_line({{"event", "finished"}, {"report", (out / "index.html").string()}, {"seconds", info.total_seconds}});
  else
    std::fprintf(stderr, "report: %s (%d pass, %d deviates, %d erratum, %d unresolved) in %.1f s\n",
                 (out / "index.html").c_str(), c.pass, c.deviates, c.erratum, c.unresolved, info.total_seconds);
  if (failed > 0) throw std::runtime_error(fmt::format("{} step(s) failed; see the report", failed));
}

}  // namespace

void register_reproduce(CLI::App& app) {
  auto a = std::make_shared<ReproduceArgs>();
  auto* sub = app.add_subcommand(
      "reproduce",
      "Run every computation of the paper and write a static HTML report DIR/index.html: each number the paper "
      "quotes next to ours (pass / deviates / erratum / unresolved) and each figure with the paper figure it corresponds to. "
      "The report is written to DIR.partial and renamed to DIR when complete.");
  auto* quick = sub->add_flag("--quick", a->quick,
                              "smaller lattices and shorter runs where that keeps the conclusion (default; under a minute on 2 cores)");
  auto* full = sub->add_flag("--full", a->full, "the paper's lattice sizes and run times (tens of minutes)");
  quick->excludes(full);
  sub->add_option("--out", a->out, "report directory (default lrchain-report; must be new, empty or an earlier report, which is replaced; "
                  "never the current directory or a parent of it)")->type_name("DIR");
  add_integer(*sub, "--jobs", a->jobs, 0, 64, "steps run at the same time, in [0, 64] (default 0: one per core)");
  sub->add_option("--only", a->only, "run only these steps, comma-separated ids from --list (default: every step)")
      ->delimiter(',')->type_name("ID,...");
  sub->add_flag("--list", a->list, "list the steps and exit");
  sub->add_flag("--progress-json", a->progress_json,
                "progress on stderr as one JSON object per line instead of text: {\"event\": \"start\", \"steps\": N, ...}, "
                "{\"event\": \"step_started\", \"step\": ID, ...}, {\"event\": \"step_finished\", \"step\": ID, \"done\": K, "
                "\"steps\": N, \"failed\": ..., ...}, {\"event\": \"finished\", ...}; errors stay one line of text "
                "(lrchain.reproduce in Python reads these)");
  sub->add_option("--examples", a->examples, "directory of the experiment configs (default: the installed share/lrchain/examples, "
                  "or the source tree's examples/ for lrchain run from its build tree)")->type_name("DIR");
  sub->add_option("--errata", a->errata, "docs/paper-errata.md to include (default: the installed share/lrchain/docs/paper-errata.md, "
                  "or the source tree's for lrchain run from its build tree)")->type_name("FILE");
  add_figure_format(*sub);
  add_examples(*sub, {"lrchain reproduce --quick --out report", "lrchain reproduce --only exp1,dark_solutions --out report-part",
                      "lrchain reproduce --full --jobs 2 --out report-full"});
  sub->callback([a] { run_reproduce(*a); });
}

}  // namespace lrchain::cli

// The README's main job (issue 6): `lrchain reproduce --quick` runs every step of the paper,
// writes DIR/index.html, and headless Chromium renders it with every figure loaded and no broken
// link. The report's counts are printed for the CI log.
#include <doctest/doctest.h>

#include <unistd.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <iterator>
#include <iostream>
#include <nlohmann/json.hpp>

#include "../support/report_checks.hpp"

using namespace lrchain::test;
namespace fs = std::filesystem;

TEST_CASE("reproduce --quick: complete report, rendered by headless Chromium") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-report-quick-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto t0 = std::chrono::steady_clock::now();
  const auto run = run_lrchain({"reproduce", "--quick", "--out", dir.string()});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The last lines of its progress log, for the CI log.
  const auto& log = run.err;
  std::size_t from = log.size();
  for (int lines = 0; from > 0 && lines < 26; --from) lines += log[from - 1] == '\n';
  std::cerr << log.substr(from);
  const auto summary = nlohmann::json::parse(run.out);
  std::cerr << "reproduce --quick: " << summary["pass"] << " pass, " << summary["deviates"] << " deviates, "
            << summary["erratum"] << " erratum, " << summary["unresolved"] << " unresolved, " << summary["failed_steps"]
            << " failed steps, " << seconds << " s\n";
  CHECK(summary["failed_steps"].get<int>() == 0);
  INFO("figures not produced: ", summary["figures_missing"].dump());
  CHECK(summary["figures_missing"].empty());
  // Every step of all_steps() ran (coefficients, regime, exp1-7 with 4b/4c, 8 dark-breather branches and solutions, 3 evolutions).
  CHECK(summary["steps"].size() == 22);
  const int rows = summary["pass"].get<int>() + summary["deviates"].get<int>() + summary["erratum"].get<int>() +
                   summary["unresolved"].get<int>();
  CHECK(rows >= 70);
  // Most paper numbers are reproduced; the deviations are listed in the report and the note.
  CHECK(summary["pass"].get<int>() >= rows * 3 / 4);
  // The one known deviation is exp4c (emitting ends still nucleate the secondary breather,
  // docs/simulator.md); every dark-breather row (turning point 2.37, E_b, period doubling, rho = 1
  // site-centred real instability at 2.207, rho = 10 and rho = 0.1 branches, E_b(1200), motion at
  // rho = 1) must pass, be a documented erratum or a documented unresolved difference.
  CHECK(summary["deviates"].get<int>() <= 1);
  for (const auto& step : summary["steps"]) {
    INFO("step ", step["id"].get<std::string>());
    if (step["id"].get<std::string>().rfind("dark_", 0) == 0) CHECK(step["deviates"].get<int>() == 0);
  }
  // The report is built in DIR.partial and renamed: no file of the finished report may name that
  // directory (summary.json "out", "checkpoint_file", "command_line" are pointed at DIR).
  std::vector<std::string> naming_partial, citing_labels;
  const std::regex latex_label(R"((eq|fig|sec|tab):[A-Za-z])");
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.find(".partial") != std::string::npos) naming_partial.push_back(entry.path().string());
    // A figure script cites the paper by number (eq. (40)), never by its LaTeX label (eq:edensity).
    if (entry.path().extension() == ".gp" && std::regex_search(bytes, latex_label))
      citing_labels.push_back(entry.path().string());
  }
  INFO("figure scripts citing a LaTeX label: ", citing_labels.size(), citing_labels.empty() ? "" : ", e.g. " + citing_labels.front());
  CHECK(citing_labels.empty());
  INFO("files naming DIR.partial: ", naming_partial.size(), naming_partial.empty() ? "" : ", e.g. " + naming_partial.front());
  CHECK(naming_partial.empty());
  const auto exp6 = nlohmann::json::parse(std::ifstream(dir / "exp6" / "summary.json"));
  CHECK(exp6["out"].get<std::string>() == (dir / "exp6").string());
  for (const auto& page : {dir / "index.html", dir / "errata.html"}) {
    const auto broken = broken_links(page);
    INFO("broken links in ", page.string(), ": ", broken.size() ? broken.front() : "");
    CHECK(broken.empty());
  }
  // Errata proven by an independent computation (docs/paper-errata.md): 1.949, 1.888, Fig. 19's
  // 2.2282. Unresolved: ||x(0)||_inf at theta = pi/8 (one row, in the coefficients section), exp2's
  // E_x < 3 %, the rho = 1 bond-centred real instability at 2.207.
  CHECK(summary["erratum"].get<int>() == 3);
  CHECK(summary["unresolved"].get<int>() <= 3);
  for (const auto& page : {dir / "index.html", dir / "errata.html"}) {
    const auto r = render_in_chromium(page, dir.string() + "-chromium-profile");
    REQUIRE(r.ran);
    INFO(page.filename().string());
    if (page.filename() == "index.html") CHECK(r.images >= 25);
    CHECK(r.loaded == r.images);
    CHECK(r.broken == 0);
    const auto ragged = ragged_tables(r.dom);
    INFO("ragged: ", ragged.empty() ? "" : ragged.front());
    CHECK(ragged.empty());
    const auto paths = build_paths_in(r.dom);
    INFO("build path: ", paths.empty() ? "" : paths.front());
    CHECK(paths.empty());
    const auto labels = visible_latex_labels(r.dom);
    INFO("LaTeX label shown: ", labels.empty() ? "" : labels.front());
    CHECK(labels.empty());
  }
  fs::remove_all(dir.string() + "-chromium-profile");
}

// --figure-format png|svg|pdf: the pngcairo scripts rewritten for gnuplot's svg and pdfcairo
// terminals, and the files the commands draw in each format.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/run_lrchain.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/figure_format.hpp"

using namespace lrchain::test;
namespace fs = std::filesystem;
namespace jobs = lrchain::jobs;

namespace {

const std::string script = "if (!exists(\"outfile\")) outfile = 'branch.png'\n"
                           "set terminal pngcairo size 720,540 font ',11'\nset output outfile\nplot x\n";

// The first bytes of a file.
std::string head(const fs::path& file, std::size_t n) {
  std::ifstream in(file, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

}  // namespace

TEST_CASE("figure format: scripts and file names for png, svg and pdf") {
  jobs::set_figure_format(jobs::FigureFormat::png);
  CHECK(jobs::script_for_format(script) == script);  // png: the script as written
  CHECK(jobs::figure_file_name("dark/branch.png") == "dark/branch.png");

  jobs::set_figure_format(jobs::parse_figure_format("svg"));
  const std::string svg = jobs::script_for_format(script);
  CHECK(svg.find("set terminal svg size 720,540 dynamic background rgb 'white' font ',11'\n") != std::string::npos);
  CHECK(svg.find("outfile = 'branch.svg'") != std::string::npos);
  CHECK(svg.find("pngcairo") == std::string::npos);
  CHECK(jobs::figure_file_name("dark/branch.png") == "dark/branch.svg");
  CHECK(jobs::figure_format_name() == "svg");

  // pdf: 72 points per inch, so 720 x 540 pixels become 10 x 7.5 inches.
  jobs::set_figure_format(jobs::parse_figure_format("pdf"));
  CHECK(jobs::script_for_format(script).find("set terminal pdfcairo size 10.000in,7.500in font ',11'\n") !=
        std::string::npos);
  CHECK(jobs::figure_file_name("a.png") == "a.pdf");
  CHECK(jobs::figure_file_name("summary.json") == "summary.json");

  CHECK_THROWS_AS(jobs::parse_figure_format("jpg"), lrchain::InvalidParameter);
  jobs::set_figure_format(jobs::FigureFormat::png);
}

TEST_CASE("dark solve --figure-format svg and pdf draw SVG and PDF files — a bad format exits 2") {
  REQUIRE_MESSAGE(lrchain::program_in_path("gnuplot"), "gnuplot (Debian gnuplot-nox) is needed by this test");
  const fs::path base = fs::temp_directory_path() / ("lrchain-figure-format-" + std::to_string(::getpid()));
  fs::remove_all(base);
  for (const std::string format : {"svg", "pdf"}) {
    const fs::path out = base / format;
    const auto run = run_lrchain({"dark", "solve", "--omega-b", "2.42", "--sites", "41", "--quiet", "--figure-format",
                                  format, "--out", out.string()});
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    const auto json = nlohmann::json::parse(run.out);
    CHECK(json["figures"] == nlohmann::json::array({"profile." + format}));
    CHECK_FALSE(fs::exists(out / "profile.png"));
    if (format == "svg") CHECK(head(out / "profile.svg", 200).find("<svg") != std::string::npos);
    if (format == "pdf") CHECK(head(out / "profile.pdf", 5) == "%PDF-");
  }
  const auto bad = run_lrchain({"dark", "solve", "--omega-b", "2.3", "--figure-format", "gif", "--out",
                                (base / "gif").string()});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("figure-format") != std::string::npos);
  CHECK_FALSE(fs::exists(base / "gif"));
  fs::remove_all(base);
}

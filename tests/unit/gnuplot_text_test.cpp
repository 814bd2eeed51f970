// User text in gnuplot scripts (lrchain/jobs/gnuplot_text.hpp): quotes, backslashes, line breaks
// and every byte 0-255 become a single-quoted string that gnuplot reads back as the text (control
// characters shown as U+FFFD, a quote as U+2019) and that runs nothing. The expected strings follow
// gnuplot's documented single-quote rule (nothing substituted inside), checked by gnuplot itself;
// the quote is replaced because gnuplot 5.4 misreads two adjacent doubled quotes ('a'''' b').
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "lrchain/process.hpp"
#include "lrchain/jobs/gnuplot_text.hpp"

namespace fs = std::filesystem;
using lrchain::jobs::gnuplot_file_name;
using lrchain::jobs::gnuplot_string;
using lrchain::jobs::gnuplot_text;
using lrchain::jobs::GnuplotTextMode;

namespace {

const std::string fffd = "\xEF\xBF\xBD", apostrophe = "\xE2\x80\x99";

// Every byte 0-255 once, in order.
std::string all_bytes() {
  std::string s;
  for (int b = 0; b < 256; ++b) s += char(b);
  return s;
}

// `text` with every control byte (0-31, 127) replaced by U+FFFD and a quote by U+2019: what gnuplot
// must read back.
std::string shown(const std::string& text) {
  std::string s;
  for (char c : text) s += (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) ? fffd : c == '\'' ? apostrophe : std::string(1, c);
  return s;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("gnuplot text: quotes, line breaks and control bytes replaced, backslashes kept in plain mode") {
  CHECK(gnuplot_text("it's") == "it" + apostrophe + "s");
  CHECK(gnuplot_string("x'; system('touch p'); print '") ==
        "'x" + apostrophe + "; system(" + apostrophe + "touch p" + apostrophe + "); print " + apostrophe + "'");
  CHECK(gnuplot_text("a\\b") == "a\\b");
  CHECK(gnuplot_text("a\nb\rc") == "a" + fffd + "b" + fffd + "c");
  CHECK(gnuplot_text(std::string("a\0b", 3)) == "a" + fffd + "b");
  CHECK(gnuplot_text("ω_b") == "ω_b");  // UTF-8 and enhanced-text characters as they are
  // Enhanced mode: the enhanced-text characters and the backslash escaped.
  CHECK(gnuplot_text("x_{n}^2 @&~ a\\101", GnuplotTextMode::enhanced) == "x\\_\\{n\\}\\^2 \\@\\&\\~ a\\\\101");
  // A file name: "./" in front unless absolute, so that '<cmd' and '|cmd' are files.
  CHECK(gnuplot_file_name("<touch p.dat") == "'./<touch p.dat'");
  CHECK(gnuplot_file_name("/tmp/a.dat") == "'/tmp/a.dat'");
}

TEST_CASE("gnuplot text: every byte 0-255 stays inside one string on one line") {
  for (const auto mode : {GnuplotTextMode::plain, GnuplotTextMode::enhanced}) {
    const std::string t = gnuplot_text(all_bytes(), mode);
    for (const char c : t) {
      const auto byte = static_cast<unsigned char>(c);
      CHECK((byte >= 0x20 && byte != 0x7F && c != '\''));  // no control byte, no quote
    }
  }
}

TEST_CASE("gnuplot text: gnuplot reads every byte 0-255 and hostile titles back as text and runs nothing") {
  REQUIRE_MESSAGE(lrchain::program_in_path("gnuplot"), "gnuplot (Debian gnuplot-nox) is needed by this test");
  const fs::path d = fs::temp_directory_path() / ("lrchain-gnuplot-text-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  const std::string hostile[] = {
      all_bytes(),
      "x'; system('touch marker1'); print '",
      "x\nsystem('touch marker2')\n",
      "`touch marker3` @m \\ \\' '' '''' \"",
      "x'.system('touch marker4').'",
      std::string(5000, '\'') + "\\",
  };
  std::string script = "m = 'system(\"touch marker5\")'\nset print 'printed.txt'\n";
  std::string expected;
  for (const auto& h : hostile) {
    script += "print " + gnuplot_string(h) + "\n";
    expected += shown(h) + "\n";
  }
  // A comment line ending in the quoted text must not continue onto the next line.
  script += "# from " + gnuplot_string("a\\") + "\nprint 'end'\n";
  expected += "end\n";
  std::ofstream(d / "t.gp", std::ios::binary) << script;
  lrchain::ProcessOptions o;
  o.working_directory = d;
  o.capture_stderr = true;
  const auto r = lrchain::run_program({"gnuplot", "t.gp"}, o);
  REQUIRE_MESSAGE(r.ok(), r.error_output);
  CHECK(slurp(d / "printed.txt") == expected);
  for (int k = 1; k <= 5; ++k) CHECK(!fs::exists(d / ("marker" + std::to_string(k))));
  fs::remove_all(d);
}

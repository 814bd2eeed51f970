// Every `lrchain ... --help`, walked from the top through the "Subcommands:" lists: an example
// command line of that command in the footer, every option that takes a value marked REQUIRED or
// showing its default; and a command given without its subcommand names the ones it has.
#include <doctest/doctest.h>

#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../support/run_lrchain.hpp"

namespace {

using lrchain::test::run_lrchain;

// The lines of `text`.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// The subcommand names under "Subcommands:" in a help text.
std::vector<std::string> subcommands_in(const std::string& help) {
  std::vector<std::string> names;
  bool inside = false;
  for (const auto& line : lines_of(help)) {
    if (line == "Subcommands:") { inside = true; continue; }
    if (!inside) continue;
    if (line.rfind("  ", 0) != 0) break;
    if (line.size() > 2 && line[2] != ' ') names.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return names;
}

// Option lines that take a value ("  --name TYPE   description") but neither are marked REQUIRED
// nor say their default (or that they are required).
std::vector<std::string> options_without_default(const std::string& help) {
  static const std::regex value_option(R"(^  (-\w,)?--[\w-]+ (?!Excludes:|Needs:)\S)");
  std::vector<std::string> missing;
  for (const auto& line : lines_of(help))
    if (std::regex_search(line, value_option) && line.find("default") == std::string::npos &&
        line.find("REQUIRED") == std::string::npos && line.find("required") == std::string::npos)
      missing.push_back(line);
  return missing;
}

// Checks `lrchain <path> --help` and walks into its subcommands.
void check_help(const std::vector<std::string>& path, int& commands) {
  std::string shown = "lrchain";
  for (const auto& p : path) shown += " " + p;
  std::vector<std::string> args = path;
  args.push_back("--help");
  const auto r = run_lrchain(args);
  INFO(shown << " --help");
  REQUIRE(r.exit_code == 0);
  ++commands;
  // An example that runs this command (for the top level: any lrchain command).
  CHECK(r.out.find("Example") != std::string::npos);
  CHECK(r.out.find("\n  " + shown + (path.empty() ? " " : "")) != std::string::npos);
  const auto missing = options_without_default(r.out);
  INFO("option without a default: " << (missing.empty() ? "" : missing.front()));
  CHECK(missing.empty());
  for (const auto& sub : subcommands_in(r.out)) {
    auto deeper = path;
    deeper.push_back(sub);
    check_help(deeper, commands);
  }
}

}  // namespace

TEST_CASE("every --help shows an example and the default of every option") {
  int commands = 0;
  check_help({}, commands);
  // lrchain, coeffs, regime (intervals, map, thresholds), simulate (ring, bright, drive, modulated),
  // reproduce, sweep, and derive where it is built.
  CHECK(commands >= 12);
}

TEST_CASE("a command without its subcommand names its subcommands: exit 2, one line") {
  for (const auto& [command, names] : std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>>{
           {{"regime"}, {"intervals", "map", "thresholds"}},
           {{}, {"coeffs", "regime", "simulate", "dark", "reproduce", "sweep"}},
           {{"simulate"}, {"bright", "drive", "modulated", "ring"}}}) {
    const auto r = run_lrchain(command);
    INFO("lrchain " << (command.empty() ? "" : command.front()) << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    for (const auto& name : names) CHECK(r.err.find(name) != std::string::npos);
  }
}

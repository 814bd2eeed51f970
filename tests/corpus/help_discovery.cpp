// Reading lrchain's command tree from its --help texts (help_discovery.hpp).
#include "help_discovery.hpp"

#include <algorithm>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "lrchain/numeric_parse.hpp"
#include "lrchain/process.hpp"

namespace lrchain::corpus {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

std::optional<double> bound_value(const std::string& text) {
  try {
    return parse_number(text, "bound");
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Narrows `r` to the lower bound lo (open or closed).
void raise_lo(StatedRange& r, double lo, bool open) {
  if (lo > r.lo || (lo == r.lo && open)) r.lo = lo, r.lo_open = open;
  r.stated = true;
}
void lower_hi(StatedRange& r, double hi, bool open) {
  if (hi < r.hi || (hi == r.hi && open)) r.hi = hi, r.hi_open = open;
  r.stated = true;
}

}  // namespace

bool StatedRange::contains(double v) const {
  if (zero_allowed && v == 0) return true;
  if (!stated) return false;
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

StatedRange parse_stated_range(const std::string& help) {
  StatedRange r;
  static const std::regex cli11_range(R"(in \[([^\s\]]+) - ([^\s\]]+)\])");
  static const std::regex interval(R"(in\s*([\(\[])\s*([^,\s\]\)]+)\s*,\s*([^\]\)\s]+)\s*([\)\]]))");
  static const std::regex comparison(R"((>=|<=|>|<)\s*([-+]?(?:[0-9][0-9./eE+-]*|pi[0-9/*]*)))");
  static const std::regex zero_meaning(R"((^|[\s(,])0: )");
  std::smatch m;
  for (auto it = help.cbegin(); std::regex_search(it, help.cend(), m, cli11_range); it = m.suffix().first) {
    const auto lo = bound_value(m[1]), hi = bound_value(m[2]);
    if (lo && hi) raise_lo(r, *lo, false), lower_hi(r, *hi, false);
  }
  for (auto it = help.cbegin(); std::regex_search(it, help.cend(), m, interval); it = m.suffix().first) {
    const auto lo = bound_value(m[2]), hi = bound_value(m[3]);
    if (lo && hi) raise_lo(r, *lo, m[1] == "("), lower_hi(r, *hi, m[4] == ")");
  }
  for (auto it = help.cbegin(); std::regex_search(it, help.cend(), m, comparison); it = m.suffix().first) {
    const auto v = bound_value(m[2]);
    if (!v) continue;
    const std::string op = m[1];
    if (op == ">" || op == ">=") raise_lo(r, *v, op == ">");
    else lower_hi(r, *v, op == "<");
  }
  r.zero_allowed = std::regex_search(help, zero_meaning);
  return r;
}

bool HelpOption::is_numeric() const {
  return type == "NUM" || type == "INT" || type == "UINT" || type == "FLOAT" || type == "DOUBLE";
}
bool HelpOption::is_integer() const { return type == "INT" || type == "UINT"; }

std::string HelpCommand::joined() const {
  std::string s;
  for (const auto& p : path) s += (s.empty() ? "" : " ") + p;
  return s;
}

const HelpOption* HelpCommand::find(const std::string& option_name) const {
  for (const auto& o : options)
    if (o.name == option_name) return &o;
  return nullptr;
}

// CLI11's layout: "  --name TYPE [REQUIRED]   description", long signatures put the description
// on the next lines; subcommands as "  name   description" under "Subcommands:".
HelpCommand parse_help(const std::vector<std::string>& path, const std::string& text) {
  HelpCommand c;
  c.path = path;
  enum { none, options, subcommands } section = none;
  std::istringstream in(text);
  std::string line;
  HelpOption* last = nullptr;
  while (std::getline(in, line)) {
    if (line == "Options:") { section = options; last = nullptr; continue; }
    if (line == "Subcommands:") { section = subcommands; last = nullptr; continue; }
    if (line.empty() || line[0] != ' ') { section = line.empty() ? section : none; continue; }
    if (section == subcommands) {
      if (line.size() > 2 && line[2] != ' ') {
        const std::string rest = line.substr(2);
        c.subcommands.push_back(rest.substr(0, rest.find(' ')));
      }
      continue;
    }
    if (section != options) continue;
    if (line.rfind("  -", 0) != 0) {  // continuation of the previous description
      if (last) last->help += " " + trim(line);
      continue;
    }
    const std::string body = line.substr(2);
    const auto gap = body.find("  ");
    const std::string signature = body.substr(0, gap);
    const std::string description = gap == std::string::npos ? "" : trim(body.substr(gap));
    const auto space = signature.find(' ');
    const std::string names = signature.substr(0, space);
    const std::string rest = space == std::string::npos ? "" : signature.substr(space + 1);
    std::string long_name;
    std::istringstream ns(names);
    for (std::string n; std::getline(ns, n, ',');)
      if (n.rfind("--", 0) == 0) long_name = n.substr(2);
    if (long_name.empty() || long_name == "help") { last = nullptr; continue; }
    HelpOption o;
    o.name = long_name;
    const bool flag = rest.empty() || rest.rfind("Excludes", 0) == 0 || rest.rfind("Needs", 0) == 0;
    if (!flag) {
      const std::string first = rest.substr(0, rest.find(' '));
      o.type = first.substr(0, first.find(':'));
      o.required = rest.find("REQUIRED") != std::string::npos;
      if (rest.find(" x 2") != std::string::npos) o.arity = 2;
      else if (rest.find("...") != std::string::npos) o.arity = -1;
    }
    o.help = rest + " " + description;
    c.options.push_back(o);
    last = &c.options.back();
  }
  for (auto& o : c.options) o.range = parse_stated_range(o.help);
  return c;
}

std::vector<HelpCommand> discover_commands(const std::string& lrchain) {
  std::vector<HelpCommand> all;
  std::vector<std::vector<std::string>> todo{{}};
  while (!todo.empty()) {
    const auto path = todo.back();
    todo.pop_back();
    std::vector<std::string> argv{lrchain};
    argv.insert(argv.end(), path.begin(), path.end());
    argv.push_back("--help");
    ProcessOptions po;
    po.capture_stdout = true;
    po.capture_stderr = true;
    const ProcessResult r = run_program(argv, po);
    if (!r.ok() || r.output.empty())
      throw std::runtime_error("`lrchain " + (path.empty() ? std::string() : path.front() + " ...") +
                               " --help` failed: exit " + std::to_string(r.exit_code) + " " + r.error_output);
    HelpCommand c = parse_help(path, r.output);
    for (const auto& s : c.subcommands) {
      auto p = path;
      p.push_back(s);
      todo.push_back(p);
    }
    all.push_back(std::move(c));
  }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
  return all;
}

}  // namespace lrchain::corpus

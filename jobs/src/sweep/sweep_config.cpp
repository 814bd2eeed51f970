// Reading and checking a sweep file (sweep/sweep_config.hpp) through the strict config layer.
#include "lrchain/jobs/sweep/sweep_config.hpp"

#include "lrchain/one_line_text.hpp"
#include "lrchain/output_target.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "lrchain/jobs/sweep/sweep_memory.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

using namespace lrchain::config;

constexpr std::int64_t max_points = 1'000'000'000;

// [[axis]]: one parameter and its values (a list, or a linear or logarithmic range).
std::shared_ptr<const TableSchema> axis_schema() {
  return std::make_shared<const TableSchema>(TableSchema{
      "one axis of the sweep: a parameter of the job and its values",
      {string("parameter", "", "the parameter, as table.key of the base config (\"bright.theta\", \"model.rho\")")
           .require(),
       numbers("values", NumberRange::any(), "none", "the values, in order (instead of from/to/count)"),
       number("from", NumberRange::any(), "none", "first value of a range"),
       number("to", NumberRange::any(), "none", "last value of a range"),
       integer("count", 1, max_points, "none", "number of values of a range (from and to included)"),
       choice("spacing", {"linear", "log"}, "linear", "linear or logarithmic spacing of a range (log: from and to of the same sign)")},
      std::nullopt});
}

// A ConfigError at a key of a checked table, in the layer's wording.
ConfigError error_at(const CheckedTable& t, const std::string& table_text, const std::string& key,
                     const std::string& what) {
  return ConfigError(fmt::format("invalid value for '{}' in {} at {}:{}: {}", key, table_text, t.source(),
                                 t.line(key) ? t.line(key) : t.line(), what),
                     t.source(), t.line(key) ? t.line(key) : t.line(), t.path(), key);
}

std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One [[axis]]'s values as the file gives them: a list, or a range not generated yet.
struct AxisSpec {
  std::vector<double> listed;  // `values` (empty for a range)
  double from = 0, to = 0;
  std::int64_t count = 0;      // values of the range, or of the list
  bool log = false;
  const char* count_key = "count";  // the key that sets the number of values
};

// Reads and checks one [[axis]]'s values (every check but its parameter's name) without generating
// a range, so that its count is checked before memory is taken for it.
AxisSpec axis_spec(const CheckedTable& a) {
  const std::string where = "[[axis]]";
  AxisSpec s;
  const bool listed = a.read("values", s.listed);
  const bool ranged = a.has("from") || a.has("to") || a.has("count");
  if (listed && ranged) throw error_at(a, where, "values", "give either 'values' or 'from', 'to' and 'count', not both");
  if (listed) {
    if (s.listed.empty()) throw error_at(a, where, "values", "the list of values is empty");
    s.count = std::int64_t(s.listed.size());
    s.count_key = "values";
    return s;
  }
  for (const char* k : {"from", "to", "count"})
    if (!a.has(k)) throw error_at(a, where, k, "a range needs 'from', 'to' and 'count' (or give 'values')");
  std::string spacing = "linear";
  a.read("from", s.from);
  a.read("to", s.to);
  a.read("count", s.count);
  a.read("spacing", spacing);
  s.log = spacing == "log";
  if (s.log && !(s.from * s.to > 0))
    throw error_at(a, where, s.from != 0 ? "to" : "from", "a log range needs from and to non-zero and of the same sign");
  if (s.count > 1 && s.from == s.to) throw error_at(a, where, "to", "the range is empty: from = to with count > 1");
  return s;
}

// The values of an axis (a range generated, linear or logarithmic, with its ends exact).
std::vector<double> axis_values(AxisSpec s) {
  if (!s.listed.empty()) return std::move(s.listed);
  const double from = s.from, to = s.to;
  const std::int64_t count = s.count;
  std::vector<double> values(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    const double f = count == 1 ? 0.0 : double(i) / double(count - 1);
    values[std::size_t(i)] = s.log ? std::copysign(std::exp(std::log(std::abs(from)) + f * (std::log(std::abs(to)) - std::log(std::abs(from)))), from)
                                   : from + f * (to - from);
  }
  values.front() = from;
  if (count > 1) values.back() = to;
  return values;
}

// The most rows one point of the job can give (dark continue, bright continue: its branch points; from
// the base config's [dark] or [bright] points, or the largest value of a dark.points or bright.points axis).
double rows_per_point_bound(const Job& job, const std::vector<std::pair<std::string, AxisSpec>>& specs) {
  if (job.row_names().empty()) return 0;
  const bool dark = job.kind() == "dark continue";
  if (!dark && job.kind() != "bright continue") return 64;  // regime intervals: a few focusing intervals per branch
  const std::string table = dark ? "dark" : "bright";
  // the schema's default of [dark] or [bright] points
  double most = dark ? 100 : double(jobs::bright_breather::BrightBreatherConfig{}.points);
  if (const auto* t = job.base().root()[table].as_table())
    if (const auto points = (*t)["points"].value<std::int64_t>()) most = double(*points);
  for (const auto& [parameter, s] : specs)
    if (parameter == table + ".points") {
      most = std::max(s.from, s.to);
      for (double v : s.listed) most = std::max(most, v);
    }
  return std::max(most, 1.0);
}

// Refuses a sweep whose results do not fit in the available memory (before its axes are generated),
// naming the axis with the most values.
void check_sweep_memory(const Job& job, const std::vector<CheckedTable>& axes,
                        const std::vector<std::pair<std::string, AxisSpec>>& specs, double points, int ranks_on_node) {
  SweepMemorySizes sizes;
  sizes.points = points;
  sizes.scalars = double(job.scalar_names().size());
  sizes.row_columns = double(job.row_names().size());
  sizes.rows_per_point = rows_per_point_bound(job, specs);
  for (const auto& [parameter, s] : specs) sizes.axis_values += double(s.count);
  sizes.ranks_on_node = ranks_on_node;
  const double needed = sweep_memory_bytes(sizes), available = available_memory_bytes();
  if (available <= 0 || needed <= available) return;
  std::size_t widest = 0;
  for (std::size_t k = 0; k < specs.size(); ++k)
    if (specs[k].second.count > specs[widest].second.count) widest = k;
  throw error_at(axes[widest], "[[axis]]", specs[widest].second.count_key,
                 fmt::format("the sweep's {:.6g} points need about {} of memory ({} per point{}) but {} is available; "
                             "use fewer values or split the sweep into several files",
                             points, format_bytes(needed), format_bytes(sweep_point_bytes(sizes)),
                             ranks_on_node > 1 ? fmt::format(", {} ranks on this node", ranks_on_node) : std::string(),
                             format_bytes(available)));
}

// Why `text` cannot be one line of a label or file name (its first control character), or "".
std::string control_character_problem(const std::string& text) {
  const std::string problem = one_line_text_problem(text);
  return problem.empty() ? problem : "contains " + problem + "; give one line of printable text";
}

// Refuses a control character in the string at `key` (exit 2 naming file:line:key).
void check_one_line(const CheckedTable& t, const std::string& key, const std::string& text) {
  const std::string problem = control_character_problem(text);
  if (!problem.empty()) throw error_at(t, "the top level", key, problem);
}

}  // namespace

std::string output_problem(const std::filesystem::path& output, bool figure) {
  const std::string text = output.string();
  if (text.empty()) return "give a file name";
  if (std::string p = control_character_problem(text); !p.empty()) return p;
  if (!output.has_filename()) return "give a file name, not a directory";
  try {
    check_output_target(output);  // a device, FIFO, socket or directory is refused before any point runs
  } catch (const std::exception& e) {
    return e.what();
  }
  // The figures' files are named after the output: gnuplot is told their names in quotes and as
  // its arguments, where a name starting with '<' or '|' is a shell command and '-' an option.
  const std::string name = output.filename().string();
  if (figure && (name.find_first_of("'\\") != std::string::npos || std::string_view("<|-").find(name.front()) != std::string_view::npos))
    return "the figure's files are named after it: give a file name without quotes or backslashes, not starting with '<', '|' or '-'";
  return {};
}

const TableSchema& sweep_schema() {
  static const TableSchema s{
      "a sweep",
      {choice("job", job_kinds(), "", "the job run at every point").require(),
       string("name", "the file name without .toml", "a label recorded in the results"),
       string("base", "", "the job's base config (path relative to this file)").require(),
       string("output", "", "the results file (HDF5; path relative to the working directory)").require(),
       choice("layout", {"grid", "list"}, "grid",
              "grid: every combination of the axes' values; list: the i-th values of all axes together"),
       integer("csv_max_points", 0, max_points, "10000", "also write a CSV view (output with .csv) up to this many points"),
       number("checkpoint_seconds", NumberRange::positive(), "30", "the results file is rewritten at least this often"),
       string("figure", "none",
              "draw log10 of this scalar over a two-axis grid, or for \"dark continue\" and \"bright continue\" over one axis "
              "\"stability\": the branches in the (axis, omega_b) plane (PNG next to the output)"),
       tables("axis", axis_schema()).require()},
      std::nullopt};
  return s;
}

std::string sweep_config_markdown() {
  const TableSchema& top = sweep_schema();
  std::string md = "Top level:\n\n" + markdown_table(top);
  for (const auto& k : top.keys)
    if (k.type == ValueType::table_array) md += "\n`[[" + k.name + "]]`: " + k.table->meaning + ".\n\n" + markdown_table(*k.table);
  return md;
}

std::size_t SweepConfig::points() const {
  if (axes.empty()) return 0;
  if (!grid) return axes.front().values.size();
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.values.size();
  return n;
}

std::vector<std::size_t> SweepConfig::shape() const {
  if (!grid) return {points()};
  std::vector<std::size_t> s;
  for (const auto& a : axes) s.push_back(a.values.size());
  return s;
}

Overrides SweepConfig::overrides(std::size_t point) const {
  Overrides o(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    const auto& v = axes[k].values;
    const std::size_t i = grid ? point % v.size() : point;
    if (grid) point /= v.size();
    o[k] = {axes[k].parameter, v[i]};
  }
  return o;
}

SweepConfig load_sweep_config(const std::filesystem::path& file, int ranks_on_node,
                              std::shared_ptr<const ModelCompiler> compiler) {
  const Document doc = Document::from_file(file);
  const CheckedTable root = check(doc, sweep_schema());
  SweepConfig c;
  c.text = slurp(file);
  c.name = file.stem().string();
  root.read("name", c.name);
  root.read("job", c.job);
  std::string base, output, layout = "grid";
  root.read("base", base);
  root.read("output", output);
  root.read("layout", layout);
  c.grid = layout == "grid";
  std::int64_t csv = 0;
  if (root.read("csv_max_points", csv)) c.csv_max_points = std::size_t(csv);
  root.read("checkpoint_seconds", c.checkpoint_seconds);
  if (base.empty()) throw error_at(root, "the top level", "base", "give the base config's file name");
  check_one_line(root, "name", c.name);
  check_one_line(root, "base", base);
  c.output = output;
  c.base = std::filesystem::path(base).is_absolute() ? std::filesystem::path(base) : file.parent_path() / base;

  c.base_job = std::make_shared<const Job>(Document::from_file(c.base), std::move(compiler));
  const Job& job = *c.base_job;
  if (job.kind() != c.job)
    throw error_at(root, "the top level", "job",
                   fmt::format("the base config '{}' is a \"{}\" experiment, not \"{}\"", base, job.kind(), c.job));
  c.base_text = slurp(c.base);

  const auto axes = root.tables("axis");
  if (axes.empty()) throw error_at(root, "the top level", "axis", "give at least one [[axis]]");
  // First the names and the counts of every axis, then the memory the points need, and only then
  // the values (a count of 1e9 would take 8 GB before any check).
  std::vector<std::pair<std::string, AxisSpec>> specs;
  double grid_points = 1;
  for (const auto& a : axes) {
    std::string parameter;
    a.read("parameter", parameter);
    if (const auto renamed = job.renamed_parameter(parameter))
      throw error_at(a, "[[axis]]", "parameter",
                     fmt::format("'{}' was renamed: use {}", renamed->old_name, renamed->replacement()));
    if (!job.has_parameter(parameter)) {
      const std::string near = closest_match(parameter, job.parameters());
      throw error_at(a, "[[axis]]", "parameter",
                     fmt::format("'{}' is not a number parameter of a \"{}\" job{}", parameter, c.job,
                                 near.empty() ? "" : "; did you mean '" + near + "'?"));
    }
    for (const auto& other : specs)
      if (other.first == parameter) throw error_at(a, "[[axis]]", "parameter", "'" + parameter + "' has an axis already");
    AxisSpec spec = axis_spec(a);
    if (!c.grid && !specs.empty() && spec.count != specs.front().second.count)
      throw error_at(a, "[[axis]]", spec.count_key,
                     fmt::format("layout \"list\" needs axes of equal length: {} values here, {} on the first axis",
                                 spec.count, specs.front().second.count));
    grid_points *= double(spec.count);
    if (c.grid && grid_points > double(max_points))
      throw error_at(a, "[[axis]]", spec.count_key, "the grid has more than 1e9 points");
    specs.emplace_back(std::move(parameter), std::move(spec));
  }
  check_sweep_memory(job, axes, specs, c.grid ? grid_points : double(specs.front().second.count), ranks_on_node);
  for (auto& [parameter, spec] : specs) c.axes.push_back(Axis{parameter, axis_values(std::move(spec))});
  const bool figure_given = root.read("figure", c.figure);
  if (const std::string problem = output_problem(output, !c.figure.empty()); !problem.empty())
    throw error_at(root, "the top level", "output", problem);
  if (figure_given && c.figure.empty())
    throw error_at(root, "the top level", "figure", "give a scalar's name (leave 'figure' out for no figure)");
  if (figure_given && draws_stability_figure(c)) {
    if (c.axes.size() != 1) throw error_at(root, "the top level", "figure", "the stability figure needs exactly one axis");
  } else if (!c.figure.empty()) {
    const auto& names = job.scalar_names();
    if (std::find(names.begin(), names.end(), c.figure) == names.end()) {
      const std::string near = closest_match(c.figure, names);
      throw error_at(root, "the top level", "figure",
                     fmt::format("'{}' is not a scalar of a \"{}\" job{}", c.figure, c.job,
                                 near.empty() ? "" : "; did you mean '" + near + "'?"));
    }
    if (!c.grid || c.axes.size() != 2) throw error_at(root, "the top level", "figure", "a figure needs a grid of exactly two axes");
  }
  return c;
}

bool draws_stability_figure(const SweepConfig& c) {
  return c.figure == "stability" && (c.job == "dark continue" || c.job == "bright continue");
}

Job make_job(const SweepConfig& c) { return c.base_job ? *c.base_job : Job(Document::from_file(c.base)); }

}  // namespace lrchain::jobs::sweep

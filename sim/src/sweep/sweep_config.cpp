// Reading and checking a sweep file (sweep/sweep_config.hpp) through the strict config layer.
#include "lrchain/sim/sweep/sweep_config.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/more_experiment_config.hpp"

namespace lrchain::sim::sweep {

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

// The values of one [[axis]] (every check of the axis but its parameter's name).
std::vector<double> axis_values(const CheckedTable& a) {
  const std::string where = "[[axis]]";
  std::vector<double> values;
  const bool listed = a.read("values", values);
  const bool ranged = a.has("from") || a.has("to") || a.has("count");
  if (listed && ranged) throw error_at(a, where, "values", "give either 'values' or 'from', 'to' and 'count', not both");
  if (listed) {
    if (values.empty()) throw error_at(a, where, "values", "the list of values is empty");
    return values;
  }
  for (const char* k : {"from", "to", "count"})
    if (!a.has(k)) throw error_at(a, where, k, "a range needs 'from', 'to' and 'count' (or give 'values')");
  double from = 0, to = 0;
  std::int64_t count = 0;
  std::string spacing = "linear";
  a.read("from", from);
  a.read("to", to);
  a.read("count", count);
  a.read("spacing", spacing);
  const bool log = spacing == "log";
  if (log && !(from * to > 0))
    throw error_at(a, where, from != 0 ? "to" : "from", "a log range needs from and to non-zero and of the same sign");
  if (count > 1 && from == to) throw error_at(a, where, "to", "the range is empty: from = to with count > 1");
  values.resize(std::size_t(count));
  for (std::int64_t i = 0; i < count; ++i) {
    const double f = count == 1 ? 0.0 : double(i) / double(count - 1);
    values[std::size_t(i)] = log ? std::copysign(std::exp(std::log(std::abs(from)) + f * (std::log(std::abs(to)) - std::log(std::abs(from)))), from)
                                 : from + f * (to - from);
  }
  values.front() = from;
  if (count > 1) values.back() = to;
  return values;
}

}  // namespace

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
              "draw log10 of this scalar over a two-axis grid, or for \"dark continue\" over one axis "
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

SweepConfig load_sweep_config(const std::filesystem::path& file) {
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
  if (output.empty()) throw error_at(root, "the top level", "output", "give a file name");
  if (base.empty()) throw error_at(root, "the top level", "base", "give the base config's file name");
  c.output = output;
  c.base = std::filesystem::path(base).is_absolute() ? std::filesystem::path(base) : file.parent_path() / base;

  const Job job = make_job(c);
  if (job.kind() != c.job)
    throw error_at(root, "the top level", "job",
                   fmt::format("the base config '{}' is a \"{}\" experiment, not \"{}\"", base, job.kind(), c.job));
  c.base_text = slurp(c.base);

  const auto axes = root.tables("axis");
  if (axes.empty()) throw error_at(root, "the top level", "axis", "give at least one [[axis]]");
  double grid_points = 1;
  for (const auto& a : axes) {
    Axis axis;
    a.read("parameter", axis.parameter);
    if (const auto renamed = job.renamed_parameter(axis.parameter))
      throw error_at(a, "[[axis]]", "parameter",
                     fmt::format("'{}' was renamed: use {}", renamed->old_name, renamed->replacement()));
    if (!job.has_parameter(axis.parameter)) {
      const std::string near = closest_match(axis.parameter, job.parameters());
      throw error_at(a, "[[axis]]", "parameter",
                     fmt::format("'{}' is not a number parameter of a \"{}\" job{}", axis.parameter, c.job,
                                 near.empty() ? "" : "; did you mean '" + near + "'?"));
    }
    for (const auto& other : c.axes)
      if (other.parameter == axis.parameter)
        throw error_at(a, "[[axis]]", "parameter", "'" + axis.parameter + "' has an axis already");
    axis.values = axis_values(a);
    if (!c.grid && !c.axes.empty() && axis.values.size() != c.axes.front().values.size())
      throw error_at(a, "[[axis]]", "values",
                     fmt::format("layout \"list\" needs axes of equal length: {} values here, {} on the first axis",
                                 axis.values.size(), c.axes.front().values.size()));
    grid_points *= double(axis.values.size());
    if (c.grid && grid_points > double(max_points))
      throw error_at(a, "[[axis]]", "parameter", "the grid has more than 1e9 points");
    c.axes.push_back(std::move(axis));
  }
  const bool figure_given = root.read("figure", c.figure);
  if (figure_given && c.figure.empty())
    throw error_at(root, "the top level", "figure", "give a scalar's name (leave 'figure' out for no figure)");
  if (figure_given && c.job == "dark continue" && c.figure == "stability") {
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

Job make_job(const SweepConfig& c) { return Job(Document::from_file(c.base)); }

}  // namespace lrchain::sim::sweep

// Checking a TOML document against its schema, and reading the checked values (strict_toml.hpp).
#include <algorithm>
#include <climits>
#include <cstdio>
#include <stdexcept>

#include "lrchain/checked_number.hpp"
#include "lrchain/config/strict_toml.hpp"
#include "lrchain/numeric_parse.hpp"

namespace lrchain::config {

namespace {

enum class Verdict { ok, wrong_type, bad_value };

struct Problem {
  long line;
  std::string message, table, key;
};

std::string joined(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

// Text of user data inside a one-line message: control bytes escaped, long text cut.
std::string printable(std::string_view s) {
  constexpr std::size_t max_chars = 48;
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < max_chars; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(c));
      out += hex;
    } else {
      out += char(c);
    }
  }
  if (s.size() > max_chars) out += "...";
  return out;
}

long line_of(const toml::node& n) { return long(n.source().begin.line); }

std::string in_table(const std::string& path) {
  return path.empty() ? "in the top-level table" : "in [" + printable(path) + "]";
}

std::string location(const std::string& source, long line) {
  return line > 0 ? source + ":" + std::to_string(line) : source;
}

// The value as the user wrote it (bad_value messages) ...
std::string value_text(const toml::node& n) {
  if (auto i = n.as_integer()) return std::to_string(i->get());
  if (auto f = n.as_floating_point()) return number_text(f->get());
  if (auto s = n.as_string()) return "\"" + printable(s->get()) + "\"";
  if (auto b = n.as_boolean()) return b->get() ? "true" : "false";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date or time";
}

// ... and with its TOML type (wrong_type messages).
std::string typed_text(const toml::node& n) {
  if (n.is_integer()) return "the integer " + value_text(n);
  if (n.is_floating_point()) return "the float " + value_text(n);
  if (n.is_string()) return "the string " + value_text(n);
  if (n.is_boolean()) return "the boolean " + value_text(n);
  return value_text(n);
}

Verdict to_number(const toml::node& n, double& out) {
  if (auto i = n.as_integer()) {
    out = double(i->get());
    return Verdict::ok;
  }
  if (auto f = n.as_floating_point()) {
    out = f->get();
    return Verdict::ok;
  }
  if (auto s = n.as_string()) {
    try {
      out = parse_number(s->get(), "number");
      return Verdict::ok;
    } catch (const InvalidParameter&) {
      return Verdict::bad_value;
    }
  }
  return Verdict::wrong_type;
}

Verdict number_in(const toml::node& n, const NumberRange& range, double& out) {
  const Verdict v = to_number(n, out);
  if (v == Verdict::ok && !range.contains(out)) return Verdict::bad_value;
  return v;
}

// An integer key's value, through the one checked float-to-integer conversion.
Verdict integer_in(const toml::node& n, const KeySchema& k, std::int64_t& out) {
  double v = 0;
  const Verdict verdict = to_number(n, v);
  if (verdict != Verdict::ok) return verdict;
  try {
    out = checked_integer(v, k.name, k.min_integer, k.max_integer);
  } catch (const InvalidParameter&) {
    return Verdict::bad_value;
  }
  return Verdict::ok;
}

bool is_numeric(ValueType t) {
  return t == ValueType::number || t == ValueType::integer || t == ValueType::number_array;
}

class Checker {
 public:
  explicit Checker(const std::string& source) : source_(source) {}

  // Every key of `t` against `schema`, then the required keys.
  void check_table(const toml::table& t, const TableSchema& schema, const std::string& path) {
    for (auto&& [key, value] : t) {
      const KeySchema* k = schema.find(key.str());
      if (!k) {
        unknown(key, value, schema, path);
        continue;
      }
      check_value(value, *k, path, key.str());
    }
    for (const auto& k : schema.keys) {
      if (!k.required || t.contains(k.name)) continue;
      const bool is_table = k.type == ValueType::table || k.type == ValueType::table_array;
      // A missing key is reported at its table's header; the top level has none.
      const long line = path.empty() ? 0 : line_of(t);
      const std::string where = path.empty() ? "at the top level of " + source_
                                             : in_table(path) + " at " + location(source_, line);
      const std::string what = is_table ? "missing table [" + joined(path, k.name) + "] in " + source_
                                        : "missing key '" + k.name + "' " + where + ": expected " + k.expected();
      add(line, what, path, k.name);
    }
  }

  std::vector<Problem> problems;

 private:
  void add(long line, std::string message, const std::string& path, std::string_view key) {
    problems.push_back({line, std::move(message), path, std::string(key)});
  }

  void unknown(const toml::key& key, const toml::node& value, const TableSchema& schema, const std::string& path) {
    const long line = key.source().begin.line ? long(key.source().begin.line) : line_of(value);
    for (const auto& r : schema.renamed)
      if (key.str() == r.old_name) {
        add(line, "key '" + r.old_name + "' " + in_table(path) + " at " + location(source_, line) + " was renamed: use " +
                      r.replacement(),
            path, key.str());
        return;
      }
    std::vector<std::string> names;
    for (const auto& k : schema.keys) names.push_back(k.name);
    const auto shown = [&](const std::string& name) {
      const KeySchema* k = schema.find(name);
      if (k && k->type == ValueType::table) return "[" + joined(path, name) + "]";
      if (k && k->type == ValueType::table_array) return "[[" + joined(path, name) + "]]";
      return "'" + name + "'";
    };
    std::string message = value.is_table() || value.is_array_of_tables()
                              ? "unknown table [" + printable(joined(path, key.str())) + "] at " + location(source_, line)
                              : "unknown key '" + printable(key.str()) + "' " + in_table(path) + " at " +
                                    location(source_, line);
    if (const std::string guess = closest_match(key.str(), names); !guess.empty()) {
      message += "; did you mean " + shown(guess) + "?";
    } else if (names.empty()) {
      message += "; this table takes no keys";
    } else {
      message += "; allowed here:";
      for (std::size_t i = 0; i < names.size(); ++i) message += (i ? ", " : " ") + shown(names[i]);
    }
    add(line, message, path, key.str());
  }

  void bad(const toml::node& n, const KeySchema& k, const std::string& path, std::string_view key, Verdict v,
           const std::string& detail = "") {
    const std::string head = (v == Verdict::wrong_type ? "wrong type for '" : "invalid value for '") + printable(key) +
                             "' " + in_table(path) + " at " + location(source_, line_of(n)) + ": ";
    std::string expected = k.expected();
    if (v == Verdict::wrong_type && is_numeric(k.type))
      expected += " (a TOML number, or a number string such as \"1/3\" or \"3*pi/5\")";
    add(line_of(n), head + detail + "expected " + expected + "; got " +
                        (v == Verdict::wrong_type ? typed_text(n) : value_text(n)),
        path, key);
  }

  void check_value(const toml::node& n, const KeySchema& k, const std::string& path, std::string_view key) {
    double number = 0;
    std::int64_t whole = 0;
    Verdict v = Verdict::ok;
    switch (k.type) {
      case ValueType::number: v = number_in(n, k.range, number); break;
      case ValueType::integer: v = integer_in(n, k, whole); break;
      case ValueType::boolean: v = n.is_boolean() ? Verdict::ok : Verdict::wrong_type; break;
      case ValueType::string: v = n.is_string() ? Verdict::ok : Verdict::wrong_type; break;
      case ValueType::choice: {
        auto s = n.as_string();
        if (!s) {
          v = Verdict::wrong_type;
          break;
        }
        if (std::find(k.choices.begin(), k.choices.end(), s->get()) != k.choices.end()) break;
        const std::string guess = closest_match(s->get(), k.choices);
        bad(n, k, path, key, Verdict::bad_value);
        if (!guess.empty()) problems.back().message += "; did you mean \"" + guess + "\"?";
        return;
      }
      case ValueType::number_array:
      case ValueType::string_array: {
        auto a = n.as_array();
        if (!a) {
          v = Verdict::wrong_type;
          break;
        }
        for (std::size_t i = 0; i < a->size(); ++i) {
          const toml::node& e = *a->get(i);
          const Verdict ev = k.type == ValueType::number_array ? number_in(e, k.range, number)
                                                               : (e.is_string() ? Verdict::ok : Verdict::wrong_type);
          if (ev != Verdict::ok) {
            bad(e, k, path, key, ev, "element " + std::to_string(i + 1) + ": ");
            return;
          }
        }
        break;
      }
      case ValueType::table:
        if (auto t = n.as_table()) check_table(*t, *k.table, joined(path, key));
        else v = Verdict::wrong_type;
        break;
      case ValueType::any: break;
      case ValueType::table_array: {
        auto a = n.as_array();
        if (!a || !a->is_array_of_tables()) {
          v = Verdict::wrong_type;
          break;
        }
        for (std::size_t i = 0; i < a->size(); ++i)
          check_table(*a->get(i)->as_table(), *k.table, joined(path, key) + "[" + std::to_string(i + 1) + "]");
        break;
      }
    }
    if (v != Verdict::ok) bad(n, k, path, key, v);
  }

  const std::string& source_;
};

}  // namespace

CheckedTable check(const Document& doc, const TableSchema& root) {
  Checker checker(doc.source());
  checker.check_table(doc.root(), root, "");
  if (!checker.problems.empty()) {
    // The first problem in the file (problems without a line, e.g. a missing table, last).
    const auto first = std::min_element(checker.problems.begin(), checker.problems.end(),
                                        [](const Problem& a, const Problem& b) {
                                          const long la = a.line > 0 ? a.line : LONG_MAX;
                                          const long lb = b.line > 0 ? b.line : LONG_MAX;
                                          return la < lb;
                                        });
    throw ConfigError(first->message, doc.source(), first->line, first->table, first->key);
  }
  return CheckedTable(doc.root(), root, std::make_shared<const std::string>(doc.source()), "");
}

const toml::node* CheckedTable::node(std::string_view key, ValueType type) const {
  const KeySchema* k = schema_->find(key);
  const bool same = k && (k->type == type || (type == ValueType::string && k->type == ValueType::choice));
  if (!same) throw std::logic_error("config key '" + std::string(key) + "' is not in the schema of [" + path_ +
                                    "] with the type read");
  return table_->get(key);
}

long CheckedTable::line() const { return line_of(*table_); }

bool CheckedTable::has(std::string_view key) const { return table_->contains(key); }

std::vector<std::string> CheckedTable::keys() const {
  std::vector<std::string> out;
  for (auto&& [key, value] : *table_) out.emplace_back(key.str());
  return out;
}

long CheckedTable::line(std::string_view key) const {
  const toml::node* n = table_->get(key);
  return n ? line_of(*n) : 0;
}

bool CheckedTable::read(std::string_view key, double& out) const {
  const toml::node* n = node(key, ValueType::number);
  if (!n) return false;
  to_number(*n, out);
  return true;
}

bool CheckedTable::read(std::string_view key, std::int64_t& out) const {
  const toml::node* n = node(key, ValueType::integer);
  if (!n) return false;
  integer_in(*n, *schema_->find(key), out);
  return true;
}

bool CheckedTable::read(std::string_view key, bool& out) const {
  const toml::node* n = node(key, ValueType::boolean);
  if (!n) return false;
  out = n->as_boolean()->get();
  return true;
}

bool CheckedTable::read(std::string_view key, std::string& out) const {
  const toml::node* n = node(key, ValueType::string);
  if (!n) return false;
  out = n->as_string()->get();
  return true;
}

bool CheckedTable::read(std::string_view key, std::vector<double>& out) const {
  const toml::node* n = node(key, ValueType::number_array);
  if (!n) return false;
  out.clear();
  for (const auto& e : *n->as_array()) {
    double v = 0;
    to_number(e, v);
    out.push_back(v);
  }
  return true;
}

bool CheckedTable::read(std::string_view key, std::vector<std::string>& out) const {
  const toml::node* n = node(key, ValueType::string_array);
  if (!n) return false;
  out.clear();
  for (const auto& e : *n->as_array()) out.push_back(e.as_string()->get());
  return true;
}

std::optional<double> CheckedTable::number(std::string_view key) const {
  double v = 0;
  if (!read(key, v)) return std::nullopt;
  return v;
}

std::optional<CheckedTable> CheckedTable::table(std::string_view key) const {
  const toml::node* n = node(key, ValueType::table);
  if (!n) return std::nullopt;
  return CheckedTable(*n->as_table(), *schema_->find(key)->table, source_, joined(path_, key));
}

std::vector<CheckedTable> CheckedTable::tables(std::string_view key) const {
  const toml::node* n = node(key, ValueType::table_array);
  std::vector<CheckedTable> out;
  if (!n) return out;
  const auto& a = *n->as_array();
  for (std::size_t i = 0; i < a.size(); ++i)
    out.push_back(CheckedTable(*a.get(i)->as_table(), *schema_->find(key)->table, source_,
                               joined(path_, key) + "[" + std::to_string(i + 1) + "]"));
  return out;
}

}  // namespace lrchain::config

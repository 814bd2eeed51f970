// Config schemas as data (strict_toml.hpp): key builders, the text of what a key allows, and the
// Markdown table the docs show.
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "lrchain/config/strict_toml.hpp"

namespace lrchain::config {

bool NumberRange::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (min && (min_open ? !(v > *min) : !(v >= *min))) return false;
  if (max && (max_open ? !(v < *max) : !(v <= *max))) return false;
  return true;
}

// "> 0", ">= 0", "< 1", "in (0, 1)", "" (any finite number).
std::string NumberRange::text() const {
  if (min && max)
    return "in " + std::string(min_open ? "(" : "[") + number_text(*min) + ", " + number_text(*max) +
           (max_open ? ")" : "]");
  if (min) return std::string(min_open ? "> " : ">= ") + number_text(*min);
  if (max) return std::string(max_open ? "< " : "<= ") + number_text(*max);
  return "";
}

std::string number_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

KeySchema KeySchema::require() const {
  KeySchema k = *this;
  k.required = true;
  return k;
}

namespace {

std::string joined_choices(const std::vector<std::string>& choices) {
  std::string s;
  for (const auto& c : choices) s += (s.empty() ? "\"" : ", \"") + c + "\"";
  return s;
}

std::string finite_numbers(const NumberRange& r, bool plural) {
  const std::string condition = r.text();
  return std::string(plural ? "finite numbers" : "a finite number") + (condition.empty() ? "" : " " + condition);
}

KeySchema make(std::string name, ValueType type, std::string default_text, std::string meaning) {
  KeySchema k;
  k.name = std::move(name);
  k.type = type;
  k.default_text = std::move(default_text);
  k.meaning = std::move(meaning);
  return k;
}

}  // namespace

std::string KeySchema::expected() const {
  switch (type) {
    case ValueType::number: return finite_numbers(range, false);
    case ValueType::integer:
      return "an integer in [" + std::to_string(min_integer) + ", " + std::to_string(max_integer) + "]";
    case ValueType::boolean: return "true or false";
    case ValueType::string: return "a string";
    case ValueType::choice: return "one of " + joined_choices(choices);
    case ValueType::number_array: return "an array of " + finite_numbers(range, true);
    case ValueType::string_array: return "an array of strings";
    case ValueType::table: return "a table [" + name + "]";
    case ValueType::table_array: return "an array of tables [[" + name + "]]";
    case ValueType::any: return "any value";
  }
  return "";
}

KeySchema number(std::string name, NumberRange range, std::string default_text, std::string meaning) {
  KeySchema k = make(std::move(name), ValueType::number, std::move(default_text), std::move(meaning));
  k.range = range;
  return k;
}

KeySchema integer(std::string name, std::int64_t min, std::int64_t max, std::string default_text,
                  std::string meaning) {
  constexpr std::int64_t exact = std::int64_t(1) << 53;  // every integer up to here is a double
  if (min > max || min < -exact || max > exact)
    throw std::logic_error("integer key '" + name + "': bounds must satisfy -2^53 <= min <= max <= 2^53");
  KeySchema k = make(std::move(name), ValueType::integer, std::move(default_text), std::move(meaning));
  k.min_integer = min;
  k.max_integer = max;
  return k;
}

KeySchema boolean(std::string name, std::string default_text, std::string meaning) {
  return make(std::move(name), ValueType::boolean, std::move(default_text), std::move(meaning));
}

KeySchema string(std::string name, std::string default_text, std::string meaning) {
  return make(std::move(name), ValueType::string, std::move(default_text), std::move(meaning));
}

KeySchema choice(std::string name, std::vector<std::string> allowed, std::string default_text, std::string meaning) {
  KeySchema k = make(std::move(name), ValueType::choice, std::move(default_text), std::move(meaning));
  k.choices = std::move(allowed);
  return k;
}

KeySchema numbers(std::string name, NumberRange each, std::string default_text, std::string meaning) {
  KeySchema k = make(std::move(name), ValueType::number_array, std::move(default_text), std::move(meaning));
  k.range = each;
  return k;
}

KeySchema strings(std::string name, std::string default_text, std::string meaning) {
  return make(std::move(name), ValueType::string_array, std::move(default_text), std::move(meaning));
}

KeySchema table(std::string name, std::shared_ptr<const TableSchema> schema) {
  KeySchema k = make(std::move(name), ValueType::table, "", schema ? schema->meaning : "");
  k.table = std::move(schema);
  return k;
}

KeySchema tables(std::string name, std::shared_ptr<const TableSchema> schema) {
  KeySchema k = make(std::move(name), ValueType::table_array, "", schema ? schema->meaning : "");
  k.table = std::move(schema);
  return k;
}

KeySchema anything(std::string name) { return make(std::move(name), ValueType::any, "", ""); }

const KeySchema* TableSchema::find(std::string_view key) const {
  for (const auto& k : keys)
    if (k.name == key) return &k;
  return other_keys ? &*other_keys : nullptr;
}

namespace {

std::string cell(std::string text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::string markdown_table(const TableSchema& schema) {
  std::string md = "| key | value | default | meaning |\n|---|---|---|---|\n";
  for (const auto& k : schema.keys) {
    if (k.type == ValueType::table || k.type == ValueType::table_array) continue;  // own section
    md += "| `" + k.name + "` | " + cell(k.expected()) + " | " +
          cell(k.required ? "required" : k.default_text) + " | " + cell(k.meaning) + " |\n";
  }
  if (schema.other_keys)
    md += "| *any other name* | " + cell(schema.other_keys->expected()) + " | | " + cell(schema.other_keys->meaning) +
          " |\n";
  return md;
}

}  // namespace lrchain::config

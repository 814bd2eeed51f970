#pragma once
// Strict TOML configs: every config file (simulate experiments, and the same way sweep configs and
// model files) declares its tables as a schema — the allowed keys, each with a type, a range or a
// list of allowed values, required or optional, a default and a one-line meaning — and is read
// only through this layer. Anything the schema does not allow is a ConfigError (exit 2, one line)
// naming the file and line, the table, the key and what is allowed:
//   unknown key 'kapa' in [model] at exp1.toml:7; did you mean 'kappa'?
// Usage:
//   const TableSchema model{"the lattice", {number("rho", NumberRange::positive(), "1/3", "mass ratio"), ...}};
//   const TableSchema root{"", {choice("experiment", {"bright"}, "", "...").require(), table("model", model)}};
//   const Document doc = Document::from_file(path);          // missing/empty/binary/malformed: ConfigError
//   const CheckedTable config = check(doc, root);             // every key, type and range checked here
//   if (auto m = config.table("model")) m->read("rho", params.rho);  // keeps the default if absent
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "lrchain/config/renamed_key.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::config {

// A config problem, located: what() is the whole one-line message.
class ConfigError : public InputError {
 public:
  ConfigError(const std::string& message, std::string source, long line, std::string table, std::string key)
      : InputError(message), source_(std::move(source)), line_(line), table_(std::move(table)), key_(std::move(key)) {}
  const std::string& source() const noexcept { return source_; }  // the file as named by the user
  long line() const noexcept { return line_; }                    // 1-based; 0 when there is none
  const std::string& table() const noexcept { return table_; }    // dotted path, "" for the top level
  const std::string& key() const noexcept { return key_; }        // "" for file-level problems

 private:
  std::string source_;
  long line_;
  std::string table_, key_;
};

// The allowed values of a number: always finite, optionally bounded below and/or above.
struct NumberRange {
  std::optional<double> min, max;
  bool min_open = false, max_open = false;  // true: > min (< max); false: >= min (<= max)

  static NumberRange any() { return {}; }
  static NumberRange positive() { return {0.0, std::nullopt, true, false}; }
  static NumberRange non_negative() { return {0.0, std::nullopt, false, false}; }
  static NumberRange above(double v) { return {v, std::nullopt, true, false}; }
  static NumberRange at_least(double v) { return {v, std::nullopt, false, false}; }
  // [lo, hi], (lo, hi), [lo, hi) or (lo, hi].
  static NumberRange between(double lo, double hi, bool lo_open, bool hi_open) { return {lo, hi, lo_open, hi_open}; }

  bool contains(double v) const;
  std::string text() const;  // "a finite number > 0", "a finite number in [0, 1)"
};

// `any` accepts every value unchecked: for a first look at one key (e.g. which kind of config a file is)
// before the whole file is checked against that kind's schema.
enum class ValueType { number, integer, boolean, string, choice, number_array, string_array, table, table_array, any };

struct TableSchema;

// One allowed key. Build it with number(), integer(), ... below.
struct KeySchema {
  std::string name;
  ValueType type = ValueType::number;
  bool required = false;
  NumberRange range;                         // number, and each number_array element
  std::int64_t min_integer = 0, max_integer = 0;  // integer: [min, max], |bounds| <= 2^53
  std::vector<std::string> choices;          // choice: the allowed strings
  std::shared_ptr<const TableSchema> table;  // table, and each table_array element
  std::string default_text;                  // shown in the docs ("500", "rkf78", "none")
  std::string meaning;                       // one line for the docs

  KeySchema require() const;     // this key must be present
  std::string expected() const;  // "a finite number > 0", "an integer in [2, 50000000]", ...
};

// A number: a TOML integer or float, or a string in lrchain's number syntax ("1/3", "3*pi/5").
KeySchema number(std::string name, NumberRange range, std::string default_text, std::string meaning);
// An integer: a TOML integer, or an integral float or number string (1e3), in [min, max].
KeySchema integer(std::string name, std::int64_t min, std::int64_t max, std::string default_text,
                  std::string meaning);
KeySchema boolean(std::string name, std::string default_text, std::string meaning);
KeySchema string(std::string name, std::string default_text, std::string meaning);  // free text
KeySchema choice(std::string name, std::vector<std::string> allowed, std::string default_text, std::string meaning);
KeySchema numbers(std::string name, NumberRange each, std::string default_text, std::string meaning);
KeySchema strings(std::string name, std::string default_text, std::string meaning);
KeySchema table(std::string name, std::shared_ptr<const TableSchema> schema);    // [name]
KeySchema tables(std::string name, std::shared_ptr<const TableSchema> schema);   // [[name]]
KeySchema anything(std::string name);                                              // ValueType::any

// The keys allowed in one table. `other_keys`, when set, is the schema of every key not listed
// (user-named entries such as a model's parameters); its name is ignored. Otherwise an unlisted
// key is an error.
struct TableSchema {
  std::string meaning;
  std::vector<KeySchema> keys;
  std::optional<KeySchema> other_keys;
  // Keys that were renamed: {old, new} or {old, new, note}. The old key is an error naming the new one.
  std::vector<RenamedKey> renamed = {};

  const KeySchema* find(std::string_view key) const;  // listed key, else other_keys, else nullptr
};

// A parsed TOML document and the name its messages use for it.
class Document {
 public:
  // Reads a config file: a missing file, a directory, an unreadable, empty, binary (NUL bytes,
  // invalid UTF-8) or over-large (> 4 MiB) file and a TOML syntax error are ConfigErrors naming
  // the file (and line).
  static Document from_file(const std::filesystem::path& file);
  // Parses TOML text; `source` names it in messages (a file name).
  static Document from_text(std::string_view text, std::string source);

  const std::string& source() const noexcept { return source_; }
  const toml::table& root() const noexcept { return root_; }

 private:
  Document(toml::table root, std::string source) : root_(std::move(root)), source_(std::move(source)) {}
  toml::table root_;
  std::string source_;
};

// A table that has passed its schema: reading a key gives the checked, converted value.
// Asking for a key the schema does not list, or as another type, is a programming error
// (std::logic_error).
class CheckedTable {
 public:
  const std::string& source() const noexcept { return *source_; }
  const std::string& path() const noexcept { return path_; }  // "model", "sweep.axes", "" (top level)
  long line() const;                                          // where the table starts (0: unknown)

  bool has(std::string_view key) const;
  std::vector<std::string> keys() const;  // the keys present, sorted
  long line(std::string_view key) const;  // line of the key's value (0: absent)

  // Each read() leaves `out` untouched and returns false when the key is absent.
  bool read(std::string_view key, double& out) const;                    // number
  bool read(std::string_view key, std::int64_t& out) const;              // integer
  bool read(std::string_view key, bool& out) const;                      // boolean
  bool read(std::string_view key, std::string& out) const;               // string or choice
  bool read(std::string_view key, std::vector<double>& out) const;       // number_array
  bool read(std::string_view key, std::vector<std::string>& out) const;  // string_array
  std::optional<double> number(std::string_view key) const;
  std::optional<CheckedTable> table(std::string_view key) const;  // table
  std::vector<CheckedTable> tables(std::string_view key) const;   // table_array (empty if absent)

 private:
  friend CheckedTable check(const Document&, const TableSchema&);
  CheckedTable(const toml::table& t, const TableSchema& s, std::shared_ptr<const std::string> source,
               std::string path)
      : table_(&t), schema_(&s), source_(std::move(source)), path_(std::move(path)) {}
  const toml::node* node(std::string_view key, ValueType type) const;

  const toml::table* table_;
  const TableSchema* schema_;
  std::shared_ptr<const std::string> source_;
  std::string path_;
};

// Checks the whole document against the schema of its top level (every table, key, type and
// range, recursively): ConfigError on the first problem, in file order. The document and the
// schema must outlive the result.
CheckedTable check(const Document& doc, const TableSchema& root);

// Closest of `candidates` to `word` by edit distance (Damerau-Levenshtein, case-insensitive), if
// close enough to be a likely typo; "" otherwise.
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

// A Markdown table (key | type and range | default | meaning) of one table's keys, for the docs.
std::string markdown_table(const TableSchema& schema);

// Shortest text that reads back as the same double ("0.25", "1e-12", "200"): for default_text.
std::string number_text(double v);

}  // namespace lrchain::config

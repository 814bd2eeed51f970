// Generating the bad-input corpus (corpus_case.hpp) from --help, examples/*.toml and the tables.
#include "corpus_case.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <tuple>
#include <toml++/toml.h>

#include "corpus_tables.hpp"
#include "lrchain/numeric_parse.hpp"
#include "lrchain/jobs/experiment_config.hpp"

namespace lrchain::corpus {

namespace {

// The keys of [table] in a config of `kind` that were renamed (the schema's RenamedKey list); none
// for a kind or table the schema does not know.
std::vector<config::RenamedKey> renamed_keys(const std::string& kind, const std::string& table) {
  const auto kinds = jobs::experiment_kinds();
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) return {};
  const config::KeySchema* t = jobs::experiment_schema(kind).find(table);
  return t && t->table ? t->table->renamed : std::vector<config::RenamedKey>{};
}

const HelpCommand* find_command(const std::vector<HelpCommand>& commands, const std::string& joined) {
  for (const auto& c : commands)
    if (c.joined() == joined) return &c;
  return nullptr;
}

// True when `joined` or a command above it (whose options its subcommands accept) has --option.
bool accepts_option(const std::vector<HelpCommand>& commands, const std::string& joined, const std::string& option) {
  for (std::string j = joined;;) {
    if (const HelpCommand* c = find_command(commands, j); c && c->find(option)) return true;
    const auto space = j.rfind(' ');
    if (space == std::string::npos) return false;
    j = j.substr(0, space);
  }
}

std::vector<std::string> split_path(const std::string& joined) {
  std::vector<std::string> path;
  std::istringstream in(joined);
  for (std::string w; in >> w;) path.push_back(w);
  return path;
}

// The base command line of `joined` without `--option` and its values.
std::vector<std::string> base_without(const std::string& joined, const std::string& option) {
  std::vector<std::string> args = split_path(joined), out;
  const auto& base = base_commands().at(joined);
  args.insert(args.end(), base.begin(), base.end());
  bool skipping = false;
  for (const auto& a : args) {
    if (a.rfind("--", 0) == 0) skipping = a == "--" + option || a.rfind("--" + option + "=", 0) == 0;
    if (!skipping) out.push_back(a);
  }
  return out;
}

// The command-line text of a corpus value for an option of this type.
std::string option_text(BadValue v, bool integer) {
  switch (v) {
    case BadValue::nan: return "nan";
    case BadValue::inf: return "inf";
    case BadValue::minus_inf: return "-inf";
    case BadValue::minus_one: return "-1";
    case BadValue::zero: return "0";
    case BadValue::huge: return "1e308";
    case BadValue::huge_pi: return "1e300pi";
    case BadValue::empty: return "";
    case BadValue::word: return "many";
    case BadValue::wrong_type: return integer ? "2.5" : "true";  // a fraction for a count, a boolean for a number
  }
  return {};
}

// The TOML text of a corpus value: numbers as TOML numbers, the rest as strings; the wrong type
// is a table where a value belongs.
std::string toml_text(BadValue v) {
  switch (v) {
    case BadValue::nan: return "nan";
    case BadValue::inf: return "inf";
    case BadValue::minus_inf: return "-inf";
    case BadValue::minus_one: return "-1";
    case BadValue::zero: return "0";
    case BadValue::huge: return "1e308";
    case BadValue::huge_pi: return "\"1e300pi\"";
    case BadValue::empty: return "\"\"";
    case BadValue::word: return "\"many\"";
    case BadValue::wrong_type: return "{ value = 1 }";
  }
  return {};
}

// -1 and 0 are skipped where the option's stated range (or the table) allows them; the table
// may also allow other values (a word as a run name).
bool may_be_valid(BadValue v, const StatedRange* range, const std::string& name) {
  if (possibly_valid(name).count(v)) return true;
  if (!range) return false;
  if (v == BadValue::minus_one) return range->contains(-1.0);
  if (v == BadValue::zero) return range->contains(0.0);
  return false;
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

// Replaces the text of a single-line TOML node (source columns are 1-based, end exclusive).
std::string replace_node(const std::vector<std::string>& lines, const toml::node& n, const std::string& text) {
  auto out = lines;
  const auto& src = n.source();
  std::string& line = out.at(src.begin.line - 1);
  line = line.substr(0, src.begin.column - 1) + text + line.substr(src.end.column - 1);
  return join_lines(out);
}

std::string node_text(const std::vector<std::string>& lines, const toml::node& n) {
  const auto& src = n.source();
  return lines.at(src.begin.line - 1).substr(src.begin.column - 1, src.end.column - src.begin.column);
}

// Edit distance ignoring case (a product may suggest the closest key either way).
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// A misspelling of `key` whose closest key is `key` alone: a letter dropped (kappa -> kapa), the last
// letter doubled, or a stray letter in front (N -> xN, as NN would be as close to n0 as to N).
std::string typo_of(const std::string& key, const std::set<std::string>& taken) {
  std::vector<std::string> candidates;
  if (key.size() >= 4) candidates.push_back(std::string(key).erase(key.size() / 2, 1));
  candidates.push_back(key + key.back());
  candidates.push_back("x" + key);
  for (const auto& t : candidates) {
    bool unique = true;
    for (const auto& other : taken) unique = unique && (other == key || distance(t, other) > distance(t, key));
    if (unique) return t;
  }
  return candidates.back();
}

bool is_number_text(const std::string& s) {
  try {
    parse_number(s, "value");
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

void add_option_cases(const std::vector<HelpCommand>& commands, Corpus& corpus) {
  for (const auto& [joined, base] : base_commands()) {
    if (!find_command(commands, joined)) {
      corpus.errors.push_back("the base table names '" + joined + "', which `lrchain --help` does not list");
      continue;
    }
    CorpusCase control;
    control.category = "control";
    control.description = "valid base: lrchain " + joined;
    control.args = base_without(joined, "");
    control.control = true;
    corpus.cases.push_back(control);
  }
  for (const auto& name : numeric_text_options()) {
    bool found = false;
    for (const auto& c : commands) found = found || c.find(name);
    if (!found) corpus.errors.push_back("table option --" + name + " is in no --help");
  }
  for (const auto& c : commands) {
    for (const auto& o : c.options) {
      if (!o.is_numeric() && !numeric_text_options().count(o.name)) continue;
      if (!base_commands().count(c.joined())) {
        corpus.errors.push_back("'" + c.joined() + "' has numeric option --" + o.name +
                                " but no base command in corpus_tables.cpp");
        continue;
      }
      for (BadValue v : kAllBadValues) {
        if (may_be_valid(v, o.range.stated || o.range.zero_allowed ? &o.range : nullptr, o.name)) {
          ++corpus.skipped_as_valid["option value"];
          continue;
        }
        CorpusCase k;
        k.category = "option value";
        k.value = label(v);
        k.args = base_without(c.joined(), o.name);
        if (auto it = option_context().find(o.name); it != option_context().end())
          k.args.insert(k.args.end(), it->second.begin(), it->second.end());
        const std::string text = option_text(v, o.is_integer());
        if (o.arity == 2) {
          k.args.insert(k.args.end(), {"--" + o.name, pair_partner().at(o.name), text});
          k.description = c.joined() + " --" + o.name + " " + pair_partner().at(o.name) + " '" + text + "'";
        } else {
          k.args.push_back("--" + o.name + "=" + text);
          k.description = c.joined() + " --" + o.name + "='" + text + "'";
        }
        k.description += " (" + std::string(label(v)) + ")";
        k.names = {o.name};
        corpus.cases.push_back(std::move(k));
      }
    }
  }
}

void add_config_cases(const std::filesystem::path& examples, const std::vector<HelpCommand>& commands,
                      Corpus& corpus) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(examples))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) corpus.errors.push_back("no examples/*.toml in " + examples.string());
  std::set<std::string> seen;  // kind/table/key already covered by an earlier file
  for (const auto& file : files) {
    const std::string text = read_file(file), base = file.filename().string();
    const auto lines = lines_of(text);
    toml::table root;
    try {
      root = toml::parse(text, file.string());
    } catch (const toml::parse_error& e) {
      corpus.errors.push_back("shipped example " + base + " does not parse: " + std::string(e.description()));
      continue;
    }
    const std::string kind = root["experiment"].value_or(std::string("?"));
    const HelpCommand* command = find_command(commands, command_for_experiment(kind));
    if (!command) corpus.errors.push_back(base + ": experiment kind '" + kind + "' has no subcommand");

    // Every (table, key, value node) of the file, top-level keys with table "".
    struct Entry { std::string table, key; const toml::node* node; std::set<std::string> siblings; };
    std::vector<Entry> entries;
    std::set<std::string> top_keys;
    for (const auto& [k, n] : root) top_keys.insert(std::string(k.str()));
    for (const auto& [k, n] : root) {
      if (const auto* t = n.as_table()) {
        std::set<std::string> keys;
        for (const auto& [k2, n2] : *t) keys.insert(std::string(k2.str()));
        for (const auto& [k2, n2] : *t) entries.push_back({std::string(k.str()), std::string(k2.str()), &n2, keys});
      } else {
        entries.push_back({"", std::string(k.str()), &n, top_keys});
      }
    }
    for (const auto& e : entries) {
      if (!seen.insert(kind + "/" + e.table + "/" + e.key).second) continue;
      const std::string where = base + (e.table.empty() ? "" : " [" + e.table + "]") + " " + e.key;
      const toml::node& node = *e.node;
      if (node.source().begin.line != node.source().end.line) {
        corpus.errors.push_back(where + " spans lines; the generator substitutes one-line values only");
        continue;
      }
      const auto* array = node.as_array();
      const bool numeric = node.is_number() || (node.is_string() && is_number_text(*node.value<std::string>())) ||
                           (array && !array->empty() && array->back().is_number());
      const std::string option = option_for_config_key(e.key);
      const HelpOption* help = numeric && command ? command->find(option) : nullptr;
      const std::vector<std::string> args = {"simulate", "--config", "@TMP@/" + base, "--out", "@OUT@"};
      for (BadValue v : kAllBadValues) {
        if (may_be_valid(v, help && (help->range.stated || help->range.zero_allowed) ? &help->range : nullptr,
                         option)) {
          ++corpus.skipped_as_valid["config value"];
          continue;
        }
        CorpusCase k;
        k.category = "config value";
        k.value = label(v);
        // In a number array the last element is replaced; the wrong type replaces the whole array.
        const toml::node& target = array && !array->empty() && v != BadValue::wrong_type ? array->back() : node;
        k.files = {{base, replace_node(lines, target, toml_text(v))}};
        k.args = args;
        k.names = {e.key};
        k.description = where + (&target == &node ? " = " : " [last element] = ") + toml_text(v) + " (" +
                        label(v) + ")";
        corpus.cases.push_back(std::move(k));
      }
      // The same value under a misspelt key, on the line after the real one.
      // Keys the config could hold: the file's and the subcommand's options.
      std::set<std::string> possible = e.siblings;
      if (command)
        for (const auto& o : command->options) {
          std::string k = o.name;
          std::replace(k.begin(), k.end(), '-', '_');
          possible.insert(k);
        }
      const std::string typo = typo_of(e.key, possible);
      auto typo_lines = lines;
      const int line = static_cast<int>(node.source().begin.line) + 1;
      typo_lines.insert(typo_lines.begin() + (line - 1), typo + " = " + node_text(lines, node));
      CorpusCase k;
      k.category = "config unknown key";
      k.value = "typo";
      k.files = {{base, join_lines(typo_lines)}};
      k.args = args;
      k.names = {typo, e.key};
      k.substrings = {base + ":" + std::to_string(line)};
      k.description = where + ": unknown key '" + typo + "' at line " + std::to_string(line) +
                      " (must name it, the file:line and suggest '" + e.key + "')";
      corpus.cases.push_back(std::move(k));
      // The key under each old name it had (with its value): refused, naming the new key.
      for (const auto& r : renamed_keys(kind, e.table)) {
        if (r.new_name != e.key) continue;
        auto old_lines = lines;
        const int at = static_cast<int>(node.source().begin.line);
        old_lines[at - 1] = r.old_name + " = " + node_text(lines, node);
        CorpusCase o;
        o.category = "config renamed key";
        o.value = "renamed";
        o.files = {{base, join_lines(old_lines)}};
        o.args = args;
        o.names = {r.old_name, e.key};
        o.substrings = {base + ":" + std::to_string(at), "was renamed"};
        o.description = where + ": the old key '" + r.old_name + "' at line " + std::to_string(at) +
                        " (must name it, the file:line and the new key '" + e.key + "')";
        corpus.cases.push_back(std::move(o));
      }
    }
  }
}

void add_file_cases(const std::vector<HelpCommand>& commands, Corpus& corpus) {
  const std::string binary("\x00\xff\xfe\x7f\x01lrchain\x00\x80\x90\n\x00", 17);
  for (const auto& f : file_options()) {
    if (!accepts_option(commands, f.command, f.option)) {
      corpus.errors.push_back("file table: '" + f.command + " --" + f.option + "' is not in --help");
      continue;
    }
    const auto base_args = f.command == "simulate" ? std::vector<std::string>{"simulate", "--out", "@OUT@"}
                                                   : base_without(f.command, f.option);
    struct Kind { std::string what, path; bool create_file, create_dir; std::string bytes; };
    std::vector<Kind> kinds;
    const std::string stem = "corpus-" + f.option;
    if (f.directory) {
      kinds = {{"missing directory", stem + "-missing", false, false, ""},
               {"a file, not a directory", stem + "-file", true, false, "not a directory\n"}};
    } else {
      kinds = {{"missing file", stem + "-missing.dat", false, false, ""},
               {"a directory, not a file", stem + "-dir.dat", false, true, ""}};
      if (f.option != "errata") {  // the errata file is Markdown: any bytes render
        kinds.push_back({"empty file", stem + "-empty.dat", true, false, ""});
        kinds.push_back({"binary file", stem + "-binary.dat", true, false, binary});
        kinds.push_back({"malformed file", stem + "-malformed.dat", true, false,
                         "experiment = \"bright\"\n[model\nrho = = 1/3\n\"unterminated\n"});
      }
    }
    for (const auto& kind : kinds) {
      CorpusCase k;
      k.category = "file";
      k.args = base_args;
      k.args.insert(k.args.end(), {"--" + f.option, "@TMP@/" + kind.path});
      if (kind.create_file) k.files = {{kind.path, kind.bytes}};
      if (kind.create_dir) k.directories = {kind.path};
      k.any_name = {kind.path, f.option};
      k.description = f.command + " --" + f.option + ": " + kind.what;
      corpus.cases.push_back(std::move(k));
    }
  }
  for (const auto& o : output_options()) {
    if (!accepts_option(commands, o.command, o.option)) {
      corpus.errors.push_back("output table: '" + o.command + " --" + o.option + "' is not in --help");
      continue;
    }
    CorpusCase k;
    k.category = "output path";
    k.args = base_without(o.command, o.option);
    const std::string path = o.is_file ? "corpus-existing-directory" : "corpus-existing-file";
    if (o.is_file) k.directories = {path};
    else k.files = {{path, "a user's file\n"}};
    k.args.insert(k.args.end(), {"--" + o.option, "@TMP@/" + path});
    k.any_name = {o.option, path};
    k.description = o.command + " --" + o.option + " is an existing " + (o.is_file ? "directory" : "file");
    corpus.cases.push_back(std::move(k));
  }
}

namespace {

// The TOML text of a corpus value for a sweep key whose file value is `node` (a string key gets
// the numbers as numbers: a wrong type; a number key gets the empty string).
std::vector<BadValue> sweep_values() {
  using enum BadValue;
  return {wrong_type, nan, inf, minus_one, zero, huge, empty};
}

}  // namespace

void add_sweep_config_cases(const std::filesystem::path& corpus_dir, Corpus& corpus) {
  const std::string base_name = "sweep_base_bright.toml";
  const std::string base_text = read_file(corpus_dir / base_name);
  if (base_text.empty()) corpus.errors.push_back("no " + base_name + " in " + corpus_dir.string());
  std::set<std::string> seen;  // table/key covered by an earlier file
  for (const std::string& file : sweep_config_files()) {
    const std::string text = read_file(corpus_dir / file);
    const auto lines = lines_of(text);
    toml::table root;
    try {
      root = toml::parse(text, file);
    } catch (const toml::parse_error& e) {
      corpus.errors.push_back("corpus sweep file " + file + " does not parse: " + std::string(e.description()));
      continue;
    }
    const std::vector<std::string> args = {"sweep", "--config", "@TMP@/" + file, "--threads", "1", "--quiet"};
    CorpusCase control;
    control.category = "control";
    control.description = "valid sweep file " + file;
    control.args = args;
    control.files = {{file, text}, {base_name, base_text}};
    control.control = true;
    corpus.cases.push_back(control);
    // Every (table, key, node): top-level keys, and the keys of each [[axis]].
    struct Entry { std::string table, key; const toml::node* node; std::set<std::string> siblings; };
    std::vector<Entry> entries;
    std::set<std::string> top_keys;
    for (const auto& [k, n] : root) top_keys.insert(std::string(k.str()));
    for (const auto& [k, n] : root) {
      if (const auto* tables = n.as_array(); tables && tables->is_array_of_tables()) {
        for (const auto& t : *tables) {
          std::set<std::string> keys;
          for (const auto& [k2, n2] : *t.as_table()) keys.insert(std::string(k2.str()));
          for (const auto& [k2, n2] : *t.as_table()) entries.push_back({std::string(k.str()), std::string(k2.str()), &n2, keys});
        }
      } else {
        entries.push_back({"", std::string(k.str()), &n, top_keys});
      }
    }
    for (const auto& e : entries) {
      if (!seen.insert(e.table + "/" + e.key).second) continue;
      const std::string where = file + (e.table.empty() ? "" : " [[" + e.table + "]]") + " " + e.key;
      const toml::node& node = *e.node;
      const auto* array = node.as_array();
      for (BadValue v : sweep_values()) {
        if (may_be_valid(v, nullptr, option_for_config_key(e.key))) {
          ++corpus.skipped_as_valid["sweep config value"];
          continue;
        }
        CorpusCase k;
        k.category = "sweep config value";
        k.value = label(v);
        const toml::node& target = array && !array->empty() && v != BadValue::wrong_type ? array->back() : node;
        k.files = {{file, replace_node(lines, target, toml_text(v))}, {base_name, base_text}};
        k.args = args;
        k.names = {e.key};
        k.description = where + (&target == &node ? " = " : " [last element] = ") + toml_text(v) + " (" + label(v) + ")";
        corpus.cases.push_back(std::move(k));
      }
      const std::string typo = typo_of(e.key, e.siblings);
      auto typo_lines = lines;
      const int line = static_cast<int>(node.source().begin.line) + 1;
      typo_lines.insert(typo_lines.begin() + (line - 1), typo + " = " + node_text(lines, node));
      CorpusCase k;
      k.category = "sweep config unknown key";
      k.value = "typo";
      k.files = {{file, join_lines(typo_lines)}, {base_name, base_text}};
      k.args = args;
      k.names = {typo};
      k.substrings = {file + ":" + std::to_string(line)};
      k.description = where + ": unknown key '" + typo + "' at line " + std::to_string(line);
      corpus.cases.push_back(std::move(k));
    }
  }
  // --output at a file that is not a results file (left as it is), or below a file.
  const std::string file = sweep_config_files().front();
  const std::string text = read_file(corpus_dir / file);
  for (const auto& [what, output, user_file] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"an existing file that is not a sweep's results", "corpus-user.h5", "corpus-user.h5"},
           {"an empty existing file", "corpus-empty.h5", "corpus-empty.h5"},
           {"below an existing file", "corpus-file/results.h5", "corpus-file"}}) {
    CorpusCase k;
    k.category = "output path";
    k.files = {{file, text}, {base_name, base_text}, {user_file, what.find("empty") != std::string::npos ? "" : "a user's file\n"}};
    k.args = {"sweep", "--config", "@TMP@/" + file, "--threads", "1", "--quiet", "--output", "@TMP@/" + output};
    k.any_name = {"output", user_file};
    k.description = "sweep --output is " + what;
    corpus.cases.push_back(std::move(k));
  }
  // The base config a sweep file names: missing, a directory, empty, binary, malformed.
  const std::string binary("\x00\xff\xfe\x7f\x01lrchain\x00\x80\x90\n\x00", 17);
  struct Kind { std::string what, path; bool create_file, create_dir; std::string bytes; };
  const std::vector<Kind> kinds = {
      {"missing file", "corpus-base-missing.toml", false, false, ""},
      {"a directory, not a file", "corpus-base-dir.toml", false, true, ""},
      {"empty file", "corpus-base-empty.toml", true, false, ""},
      {"binary file", "corpus-base-binary.toml", true, false, binary},
      {"malformed file", "corpus-base-malformed.toml", true, false, "experiment = \"bright\"\n[model\nrho = = 1/3\n"}};
  for (const auto& kind : kinds) {
    CorpusCase k;
    k.category = "file";
    std::string changed = text;
    const auto at = changed.find(base_name);
    if (at == std::string::npos) {
      corpus.errors.push_back(file + " does not name " + base_name);
      break;
    }
    changed.replace(at, base_name.size(), kind.path);
    k.files = {{file, changed}};
    if (kind.create_file) k.files.push_back({kind.path, kind.bytes});
    if (kind.create_dir) k.directories = {kind.path};
    k.args = {"sweep", "--config", "@TMP@/" + file, "--threads", "1", "--quiet"};
    k.any_name = {kind.path, "base"};
    k.description = "sweep base config: " + kind.what;
    corpus.cases.push_back(std::move(k));
  }
}

}  // namespace lrchain::corpus

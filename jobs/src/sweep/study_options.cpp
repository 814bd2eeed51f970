// A study sweep job's base table from a job's option schema (study_options.hpp).
#include "study_options.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace lrchain::jobs::sweep {

using namespace lrchain::config;

bool sweep_option(const JobOption& o, std::string_view step) {
  return !o.python.empty() && std::find(o.steps.begin(), o.steps.end(), step) != o.steps.end();
}

KeySchema sweep_option_key(const JobOption& o) {
  const std::string default_text = o.default_value.is_null()     ? (o.default_note.empty() ? "none" : o.default_note)
                                   : o.default_value.is_string() ? o.default_value.get<std::string>()
                                                                 : o.default_value.dump();
  const std::string meaning = o.doc + (o.range.empty() ? "" : " (" + o.range + ")");
  KeySchema key = o.default_value.is_string() || o.key == "branch" ? string(o.python, default_text, meaning)
                  : o.default_value.is_boolean()                   ? boolean(o.python, default_text, meaning)
                  : o.default_value.is_number_integer()            ? integer(o.python, 0, 1'000'000'000, default_text, meaning)
                                                                   : number(o.python, NumberRange::any(), default_text, meaning);
  return o.required ? key.require() : key;
}

InvalidParameter table_key_error(const Document& doc, std::string_view table, const InvalidParameter& e,
                                 const std::vector<JobOption>& options, const std::string& key) {
  std::string name = key.empty() ? e.parameter() : key;
  if (key.empty())
    for (const JobOption& o : options)
      if (o.key == name && !o.python.empty()) name = o.python;
  const std::string what = e.what(), prefix = "invalid " + e.parameter() + ": ";
  return InvalidParameter(fmt::format("[{}] {} in {}", table, name, doc.source()),
                          what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
}

}  // namespace lrchain::jobs::sweep

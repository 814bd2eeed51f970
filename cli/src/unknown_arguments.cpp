#include "unknown_arguments.hpp"

#include <cctype>
#include <cstdlib>
#include <vector>

#include <fmt/format.h>

#include "lrchain/config/strict_toml.hpp"

namespace lrchain::cli {

namespace {

// "-x", "--name", "--name=value"; not a negative number such as "-1", "-inf" or "-pi/2" (a value
// given where none was expected).
bool is_option_word(const std::string& word) {
  if (word.size() < 2 || word[0] != '-') return false;
  if (word[1] == '-') return true;
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  const bool number = end != word.c_str() || word.rfind("-pi", 0) == 0;
  return !number && std::isalpha(static_cast<unsigned char>(word[1])) != 0;
}

// The option names (without dashes) `cmd` accepts: its own and, through fallthrough, its parents'.
std::vector<std::string> option_names(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::App* at = &cmd; at != nullptr; at = at->get_fallthrough() ? at->get_parent() : nullptr) {
    for (const CLI::Option* option : at->get_options()) {
      for (const auto& name : option->get_lnames()) names.push_back(name);
      for (const auto& name : option->get_snames()) names.push_back(name);
    }
  }
  return names;
}

// The names of `cmd`'s subcommands.
std::vector<std::string> subcommand_names(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::App* sub : cmd.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

}  // namespace

std::string unknown_argument_message(const CLI::App& app) {
  // The parsed commands from the top, e.g. lrchain -> simulate -> bright; the first word left over
  // by any of them (CLI11 keeps a command's leftovers in its remaining()).
  std::vector<const CLI::App*> chain{&app};
  while (!chain.back()->get_subcommands().empty()) chain.push_back(chain.back()->get_subcommands().front());
  std::string word;
  std::size_t at = 0;  // the command that left it over
  for (; at < chain.size(); ++at) {
    const auto left = chain[at]->remaining(false);
    if (!left.empty()) {
      word = left.front();
      break;
    }
  }
  if (word.empty()) return {};
  // A word that is no option, left over above the deepest command, is that command's: in `lrchain
  // simulat bright` the misspelt word is lrchain's, not `lrchain bright`'s.
  if (!is_option_word(word)) chain.resize(at + 1);
  const CLI::App& deepest = *chain.back();
  std::string path = "lrchain";
  for (std::size_t i = 1; i < chain.size(); ++i) path += " " + chain[i]->get_name();
  const std::string see = " (see " + path + " --help)";
  if (is_option_word(word)) {
    const std::string option = word.substr(0, word.find('='));
    const std::string bare = option.substr(option.find_first_not_of('-'));
    const std::string guess = config::closest_match(bare, option_names(deepest));
    if (guess.empty()) return path + ": unknown option " + option + see;
    return path + ": unknown option " + option + "; did you mean " + (guess.size() == 1 ? "-" : "--") + guess + "?";
  }
  const std::vector<std::string> names = subcommand_names(deepest);
  if (!names.empty()) {  // a command that needs its subcommand got a word that names none
    const std::string guess = config::closest_match(word, names);
    if (guess.empty()) return path + ": unknown subcommand '" + word + "'; give one of: " + fmt::format("{}", fmt::join(names, ", ")) + see;
    return path + ": unknown subcommand '" + word + "'; did you mean " + guess + "?";
  }
  return path + ": unexpected argument '" + word + "': every value follows its --option" + see;
}

}  // namespace lrchain::cli

// Hostile model files (issue 25): every string of a model file with a control character, bytes that
// are not UTF-8, a device, a directory or an oversized file as --model, expressions whose exact
// arithmetic would not end, and a zero stiffness, through every command that reads a model file.
// Each must exit 2 naming the file (and file:line where there is a line), with nothing written,
// and no marker file in the working directory (a string of the file never runs as code; the
// corpus rule "nothing new on disk" sees it).
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "corpus_case.hpp"

namespace lrchain::corpus {

namespace {

// The commands that read --model, with the rest of a valid command line.
const std::vector<std::pair<std::string, std::vector<std::string>>>& model_commands() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> commands{
      {"coeffs", {"coeffs", "--theta", "1", "--branch", "acoustic", "--json"}},
      {"derive", {"derive", "--json"}},
      {"simulate ring",
       {"simulate", "ring", "--branch", "acoustic", "--theta", "pi/2", "--periods", "10", "--packet-width", "4", "--out",
        "@OUT@", "--json"}},
      {"dark solve", {"dark", "solve", "--omega-b", "2.42", "--sites", "21", "--quiet", "--out", "@OUT@"}}};
  return commands;
}

// A model (fput's equations) with its strings as TOML basic-string bodies; the comments give lines.
struct Strings {
  std::string name = "hostile", description = "FPUT", range = "(-inf, inf)", parameter_description = "quadratic",
              argument = "r", expression = "r + a*r^2 + b*r^3", field = "u", mass = "1",
              force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1])";
};

std::string model_text(const Strings& s) {
  return "name = \"" + s.name + "\"\n"                                                                     // 1
         "description = \"" + s.description + "\"\n"                                                      // 2
         "[parameters]\n"                                                                                 // 3
         "a = { default = \"1/4\", range = \"" + s.range + "\", description = \"" + s.parameter_description + "\" }\n"  // 4
         "b = { default = \"1/2\" }\n"                                                                    // 5
         "[functions.F]\n"                                                                                // 6
         "argument = \"" + s.argument + "\"\n"                                                            // 7
         "expression = \"" + s.expression + "\"\n"                                                        // 8
         "[[field]]\n"                                                                                    // 9
         "name = \"" + s.field + "\"\n"                                                                   // 10
         "mass = \"" + s.mass + "\"\n"                                                                    // 11
         "force = \"" + s.force + "\"\n";                                                                 // 12
}

struct StringField {
  std::string key;
  int line;
  std::string Strings::*member;
};

// The injected text: a control character (as a TOML escape), then a line that would run a command.
std::string hostile(const std::string& control) {
  return control + "#include <cstdlib>" + control + "static int m = std::system(\\\"touch marker\\\");" + control + "//";
}

CorpusCase model_case(const std::string& command, const std::vector<std::string>& rest, const std::string& what,
                      const std::string& model_path) {
  CorpusCase c;
  c.category = "model file";
  c.description = command + " --model: " + what;
  c.args = {rest.front()};
  std::size_t i = 1;
  if (command == "simulate ring" || command == "dark solve") c.args.push_back(rest[i++]);
  c.args.insert(c.args.end(), {"--model", model_path});
  c.args.insert(c.args.end(), rest.begin() + std::ptrdiff_t(i), rest.end());
  return c;
}

}  // namespace

void add_model_file_cases(Corpus& corpus) {
  const std::vector<StringField> fields{{"name", 1, &Strings::name},
                                        {"description", 2, &Strings::description},
                                        {"parameters.a.range", 4, &Strings::range},
                                        {"parameters.a.description", 4, &Strings::parameter_description},
                                        {"functions.F.argument", 7, &Strings::argument},
                                        {"functions.F.expression", 8, &Strings::expression},
                                        {"field.name", 10, &Strings::field},
                                        {"field.mass", 11, &Strings::mass},
                                        {"field.force", 12, &Strings::force}};
  const std::vector<std::pair<std::string, std::string>> controls{
      {"newline", "\\n"}, {"carriage return", "\\r"}, {"NUL", "\\u0000"}, {"escape", "\\u001b"}, {"DEL", "\\u007f"}};
  for (const auto& [command, rest] : model_commands()) {
    for (const auto& field : fields) {
      for (const auto& [control_name, control] : controls) {
        Strings s;
        s.*field.member += hostile(control);
        CorpusCase c = model_case(command, rest, field.key + " with a " + control_name + " and C++ after it", "@TMP@/m.toml");
        c.files = {{"m.toml", model_text(s)}};
        c.names = {"m.toml"};
        c.substrings = {"m.toml:" + std::to_string(field.line) + ": key " + field.key};
        corpus.cases.push_back(c);
      }
    }
    {
      Strings s;
      s.description = "caf\xff\xfe";
      CorpusCase c = model_case(command, rest, "description with bytes that are not UTF-8", "@TMP@/m.toml");
      c.files = {{"m.toml", model_text(s)}};
      c.names = {"m.toml"};
      c.substrings = {"m.toml:2"};
      corpus.cases.push_back(c);
    }
    // The last three: within the digit and degree bounds but minutes of derivation (docs/models.md:
    // at most 64 expanded terms in a law, 256 in a force).
    for (const auto& [law, why, bound] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"r + 10^10000000*r^2", "a number of ten million digits", "digits"},
             {"r + r^(10^10)", "a power of degree 10^10", "too large for exact arithmetic"},
             {"r + exp(10^10)*r^2", "exp(10^10)", "exp of a number"},
             {"2*a*b*(exp(-a*r) - exp(-2*a*r))*(a + b + 1)^600", "a power 600 of a parameter sum", "(more than 64"},
             {"r*(1 + a^3 + b^5)^99", "a power 99 of a sum of parameter powers", "(more than 64"},
             {"(1+a+b+r)^12*(2+a+r)^12*(3+b+r)^12 - (1+a+b)^12*(2+a)^12*(3+b)^12", "three factors each to the 12th",
              "(more than 64"}}) {
      Strings s;
      s.expression = law;
      CorpusCase c = model_case(command, rest, "expression with " + why, "@TMP@/m.toml");
      c.files = {{"m.toml", model_text(s)}};
      c.names = {"m.toml"};
      c.substrings = {"m.toml:8: function F", bound};
      corpus.cases.push_back(c);
    }
    {
      Strings s;
      s.expression = "r^2 + b*r^3";  // F'(0) = 0: no linear waves
      CorpusCase c = model_case(command, rest, "a zero stiffness", "@TMP@/m.toml");
      c.files = {{"m.toml", model_text(s)}};
      c.names = {"m.toml"};
      c.substrings = {"m.toml:12: force of field u: F'(0) of function F is zero"};
      corpus.cases.push_back(c);
    }
    {
      CorpusCase c = model_case(command, rest, "/dev/zero", "/dev/zero");
      c.names = {"/dev/zero"};
      c.substrings = {"/dev/zero: a character device"};
      corpus.cases.push_back(c);
    }
    {
      CorpusCase c = model_case(command, rest, "a directory named like a model file", "@TMP@/dir.toml");
      c.directories = {"dir.toml"};
      c.names = {"dir.toml"};
      corpus.cases.push_back(c);
    }
    {
      CorpusCase c = model_case(command, rest, "a file over 1 MiB", "@TMP@/big.toml");
      c.files = {{"big.toml", model_text(Strings{}) + "# " + std::string(std::size_t(1) << 20, 'x') + "\n"}};
      c.names = {"big.toml"};
      c.substrings = {"a model file must be a regular file of at most 1 MiB"};
      corpus.cases.push_back(c);
    }
  }
}

}  // namespace lrchain::corpus

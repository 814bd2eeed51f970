// Model files are data (docs/models.md, "Strings"): a control character or invalid UTF-8 in any
// string or key of a model file is refused naming file:line and the key; a description or path
// crafted as C++ (a newline, then a static initialiser that runs a command) never reaches the
// emitted code, so loading the model creates no marker file; legal but awkward strings (quotes,
// backslashes, "*/", "#include", 100 000 characters) round-trip unchanged through the compiled
// object's description.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/derivation/model_file.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/model_compiler.hpp"
#include "scratch_cache.hpp"

namespace fs = std::filesystem;
using namespace lrchain;

namespace {

// A valid model (fput's equations) with its strings as TOML basic-string bodies (escapes allowed).
struct Strings {
  std::string name = "hostile", description = "FPUT under another name", range = "(-inf, inf)",
              parameter_description = "quadratic coefficient", argument = "r", expression = "r + a*r^2 + b*r^3",
              taylor = "K2", field = "u", mass = "1", force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1])";
};

// The model file; each string's line is fixed (the comments give them, for the expected file:line).
std::string model_text(const Strings& s) {
  return "name = \"" + s.name + "\"\n"                                  // line 1
         "description = \"" + s.description + "\"\n"                   // line 2
         "[parameters]\n"                                              // line 3
         "a = { default = \"1/4\", range = \"" + s.range + "\", description = \"" + s.parameter_description +
         "\" }\n"                                                      // line 4
         "b = { default = \"1/2\" }\n"                                 // line 5
         "[functions.F]\n"                                             // line 6
         "argument = \"" + s.argument + "\"\n"                         // line 7
         "expression = \"" + s.expression + "\"\n"                     // line 8
         "taylor = [\"" + s.taylor + "\", \"K3\", \"K4\"]\n"           // line 9
         "[[field]]\n"                                                 // line 10
         "name = \"" + s.field + "\"\n"                                // line 11
         "mass = \"" + s.mass + "\"\n"                                 // line 12
         "force = \"" + s.force + "\"\n";                              // line 13
}

struct Field {
  std::string key;  // as the message names it
  int line;
  std::string Strings::*member;
};

const std::vector<Field> kFields{{"name", 1, &Strings::name},
                                 {"description", 2, &Strings::description},
                                 {"parameters.a.range", 4, &Strings::range},
                                 {"parameters.a.description", 4, &Strings::parameter_description},
                                 {"functions.F.argument", 7, &Strings::argument},
                                 {"functions.F.expression", 8, &Strings::expression},
                                 {"functions.F.taylor", 9, &Strings::taylor},
                                 {"field.name", 11, &Strings::field},
                                 {"field.mass", 12, &Strings::mass},
                                 {"field.force", 13, &Strings::force}};

// Control characters as TOML escapes: newline, carriage return, NUL, tab, escape, DEL, other C0.
const std::vector<std::string> kControls{"\\n", "\\r", "\\u0000", "\\t", "\\u001b", "\\u007f", "\\u0001", "\\r\\n"};

struct Scratch : test::ScratchCache {
  Scratch() : ScratchCache("lrchain-hostile") {}
};

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// The message of the InputError that parse_model_text throws for `text` ("" when it accepts it).
std::string refusal(const std::string& text) {
  try {
    derivation::parse_model_text(text, "hostile.toml");
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

bool one_printable_line(const std::string& message) {
  for (const char c : message)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
  return true;
}

}  // namespace

TEST_CASE("model files: a control character in any string or key is refused naming file:line and the key") {
  REQUIRE_NOTHROW(derivation::parse_model_text(model_text(Strings{}), "hostile.toml"));  // the base is valid
  int cases = 0;
  for (const auto& field : kFields) {
    for (const auto& control : kControls) {
      Strings s;
      s.*field.member = s.*field.member + control + "x";
      CAPTURE(field.key);
      CAPTURE(control);
      const std::string message = refusal(model_text(s));
      CAPTURE(message);
      CHECK(message.find("hostile.toml:" + std::to_string(field.line) + ":") == 0);
      CHECK(message.find("key " + field.key) != std::string::npos);
      CHECK(message.find("control character") != std::string::npos);
      CHECK(one_printable_line(message));
      ++cases;
    }
  }
  CHECK(cases == int(kFields.size() * kControls.size()));
  // A key with a newline (quoted keys may hold any character).
  const std::string text = model_text(Strings{}) + "[functions.\"G\\nH\"]\nargument = \"r\"\nexpression = \"r\"\n";
  CHECK_THROWS_WITH_AS(derivation::parse_model_text(text, "hostile.toml"), doctest::Contains("hostile.toml:14: key functions.G\\x0aH"),
                       InputError);
}

TEST_CASE("model files: bytes that are not UTF-8 are refused with a one-line message naming file:line") {
  for (const std::string bad : {"\xff", "\xc3", "\xed\xa0\x80", "\xc0\xaf", "\xf5\x80\x80\x80"}) {
    Strings s;
    s.description = "caf" + bad + "e";
    CAPTURE(s.description);
    const std::string message = refusal(model_text(s));
    CAPTURE(message);
    CHECK(message.find("hostile.toml:2") == 0);
    CHECK(one_printable_line(message));
  }
  Strings fine;
  fine.description = "caf\\u00e9 \xc3\xa9";  // an escape and raw UTF-8: allowed
  CHECK(derivation::parse_model_text(model_text(fine), "hostile.toml").description == "caf\xc3\xa9 \xc3\xa9");
}

TEST_CASE("model files: a description written as C++ runs nothing, adds no parameter, and is refused" *
          doctest::timeout(300)) {
  if (!model_compiler_available()) return;
  Scratch scratch;
  const fs::path marker = scratch.dir / "marker";
  // A newline ends a // comment: the lines after it would be compiled, and the initialiser run on dlopen.
  Strings s;
  s.description = "x\\n#include <cstdlib>\\nstatic int lrchain_marker = std::system(\\\"touch " + marker.string() +
                  "\\\");\\n//";
  write(scratch.dir / "code.toml", model_text(s));
  CHECK_THROWS_AS(compile_model_lattice(scratch.dir / "code.toml"), InputError);
  CHECK_THROWS_AS(compile_model_file(scratch.dir / "code.toml"), InputError);
  CHECK(!fs::exists(marker));
  // The old free-text metadata read one record per line: this description added a parameter zz.
  Strings injected;
  injected.description = "x\\nparameter zz 7 0 0 0 0 0 0 (-inf, inf)";
  write(scratch.dir / "metadata.toml", model_text(injected));
  CHECK_THROWS_WITH_AS(compile_model_file(scratch.dir / "metadata.toml"), doctest::Contains("metadata.toml:2: key description"),
                       InputError);
  CHECK(!fs::exists(scratch.dir / "cache" / "lrchain"));  // nothing compiled
}

TEST_CASE("model files: a path written as C++ is never emitted, and awkward legal strings round-trip" * doctest::timeout(600)) {
  if (!model_compiler_available()) return;
  Scratch scratch;
  // The marker is relative (a file name cannot hold '/'): the working directory is the scratch one.
  const fs::path old_cwd = fs::current_path();
  fs::current_path(scratch.dir);
  // Each name ends a // comment, runs a command in a static initialiser and swallows the rest of
  // its line into a macro (so the old emitted source compiled): in the directory and the file name.
  const auto payload = [](int k) {
    return "\n#include <cstdlib>\nstatic int lrchain_marker_" + std::to_string(k) +
           " = std::system(\"touch marker\");\n#define LRCHAIN_REST_" + std::to_string(k) + " ";
  };
  const fs::path directory = scratch.dir / ("d" + payload(1));
  fs::create_directories(directory);
  Strings s;
  s.name = "awkward";
  // Quotes, backslashes, a comment closer, a directive and a tail up to the 4096-byte limit of a string: legal in a description.
  s.description = "q\\\" b\\\\ */ /* #include <cstdlib> ??/ " + std::string(4000, 'x');
  const fs::path file = directory / ("m" + payload(2) + ".toml");
  write(file, model_text(s));
  CompiledModelInfo info;
  const auto definition = compile_model_file(file, &info);
  CHECK(definition->name == "awkward");
  CHECK(definition->description == "q\" b\\ */ /* #include <cstdlib> ??/ " + std::string(4000, 'x'));
  CHECK(definition->parameters.size() == 2);
  CHECK(definition->branch_names.size() == 1);
  CHECK(!info.library.empty());
  const auto kernels = compile_model_lattice(file, &info);
  CHECK(std::string(kernels->model_name) == "awkward");
  CHECK(!fs::exists(scratch.dir / "marker"));
  // The same numbers as the shipped fput (same equations): the object is this file's.
  const Model mine(definition), shipped = shipped_model("fput");
  const auto a = coefficients(mine, 0, 1.0), b = coefficients(shipped, 0, 1.0);
  CHECK(a.gamma == doctest::Approx(b.gamma).epsilon(1e-12));
  CHECK(a.h == doctest::Approx(b.h).epsilon(1e-12));
  fs::current_path(old_cwd);
}

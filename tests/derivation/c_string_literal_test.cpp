// derivation::c_string_literal, the one way outside text enters emitted C++: every byte 0-255, alone
// and followed by digits (an escape must not swallow them), comes back unchanged when the C++
// compiler reads the literal, and the literal itself is one line of printable ASCII.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "lrchain/derivation/c_string_literal.hpp"
#include "lrchain/model_compiler.hpp"
#include "lrchain/process.hpp"

namespace fs = std::filesystem;
using lrchain::derivation::c_string_literal;

namespace {

// Every byte, each followed by '7' and 'a' (octal and hex escapes would continue into those).
std::string every_byte() {
  std::string text;
  for (int b = 0; b < 256; ++b) {
    text += char(b);
    text += "7a";
  }
  return text;
}

}  // namespace

TEST_CASE("c_string_literal: printable ASCII only, quoted, no line break, no trigraph or comment opener") {
  const std::string literal = c_string_literal(every_byte());
  REQUIRE(literal.size() >= 2);
  CHECK(literal.front() == '"');
  CHECK(literal.back() == '"');
  for (std::size_t i = 0; i < literal.size(); ++i) {
    const auto c = static_cast<unsigned char>(literal[i]);
    CHECK_MESSAGE(c >= 0x20, "byte ", int(c), " at ", i);
    CHECK_MESSAGE(c <= 0x7e, "byte ", int(c), " at ", i);
  }
  // Inside the quotes no unescaped quote, and no '?' (trigraphs such as ??/ read as a backslash).
  const std::string inner = literal.substr(1, literal.size() - 2);
  for (std::size_t i = 0; i < inner.size(); ++i) {
    if (inner[i] == '\\') {
      i += 3;  // always a three-digit octal escape
      continue;
    }
    CHECK(inner[i] != '"');
    CHECK(inner[i] != '?');
  }
  CHECK(c_string_literal("") == "\"\"");
  CHECK(c_string_literal("a\nb") == "\"a\\012b\"");
  CHECK(c_string_literal("\"*/\\") == "\"\\042*/\\134\"");
}

TEST_CASE("c_string_literal: the C++ compiler reads back every byte 0-255 unchanged" * doctest::timeout(120)) {
  const std::string compiler = lrchain::model_compiler_path();
  if (!lrchain::program_in_path(compiler)) {
    MESSAGE("no C++ compiler: the round trip through it is not run");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("lrchain-c-literal-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string text = every_byte();
  {
    std::ofstream source(dir / "roundtrip.cpp", std::ios::binary);
    source << "#include <cstdio>\nstatic const char text[] = " << c_string_literal(text)
           << ";\nint main() { std::fwrite(text, 1, sizeof text - 1, stdout); return 0; }\n";
  }
  const auto built = lrchain::run_program({compiler, "-o", (dir / "roundtrip").string(), (dir / "roundtrip.cpp").string()});
  REQUIRE(built.ok());
  lrchain::ProcessOptions options;
  options.capture_stdout = true;
  const auto ran = lrchain::run_program({(dir / "roundtrip").string()}, options);
  REQUIRE(ran.ok());
  CHECK(ran.output.size() == text.size());
  CHECK(ran.output == text);
  fs::remove_all(dir);
}

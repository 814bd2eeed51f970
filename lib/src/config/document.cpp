// Reading and parsing a config file (strict_toml.hpp): every way a file can fail to be a TOML
// document is one ConfigError naming the file (and the line of a syntax error).
#include <algorithm>
#include <fstream>
#include <iterator>
#include <system_error>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/config/unicode_guard.hpp"

namespace lrchain::config {

namespace {

constexpr std::uintmax_t max_config_bytes = 4u << 20;  // far above any config; refuses a wrong file early

[[noreturn]] void fail(const std::string& source, const std::string& what, long line = 0) {
  throw ConfigError("config file '" + source + "' " + what, source, line, "", "");
}

// toml++ descriptions are one line today; keep ours one line whatever they become.
std::string one_line(std::string_view text) {
  std::string s;
  for (char c : text) s += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? ' ' : c;
  return s;
}

}  // namespace

Document Document::from_file(const std::filesystem::path& file) {
  const std::string source = file.string();
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) fail(source, "does not exist");
  if (std::filesystem::is_directory(status)) fail(source, "is a directory, not a TOML file");
  if (!std::filesystem::is_regular_file(status)) fail(source, "is not a regular file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) fail(source, "cannot be read (" + ec.message() + ")");
  if (size > max_config_bytes) fail(source, "is too large for a config (" + std::to_string(size) + " bytes; at most 4 MiB)");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(source, "cannot be opened for reading");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) fail(source, "cannot be read");
  return from_text(text, source);
}

Document Document::from_text(std::string_view text, std::string source) {
  if (std::all_of(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }))
    fail(source, "is empty");
  if (const auto nul = text.find('\0'); nul != std::string_view::npos)
    fail(source, "is not a text file (NUL byte at line " +
                     std::to_string(1 + std::count(text.begin(), text.begin() + long(nul), '\n')) + ")");
  if (const auto bad = detail::find_unsafe_non_ascii(text))
    throw ConfigError("malformed TOML in " + source + ":" + std::to_string(bad->line) + ": " + bad->what +
                          " (write it as a \\uXXXX escape inside a \"string\")",
                      source, bad->line, "", "");
  try {
    return Document(toml::parse(text, source), source);
  } catch (const toml::parse_error& e) {
    const long line = long(e.source().begin.line);
    throw ConfigError("malformed TOML in " + source + ":" + std::to_string(line) + ": " + one_line(e.description()),
                      source, line, "", "");
  }
}

}  // namespace lrchain::config

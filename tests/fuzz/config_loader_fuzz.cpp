// libFuzzer entry point for the config loader: the bytes are a config file's text, loaded the way
// `lrchain simulate --config` loads it (parse, check against the kind's schema, read, validate()).
// Refusing the input with an InputError is the expected outcome; anything else (a crash, another
// exception, a sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto doc = lrchain::config::Document::from_text(text, "fuzz.toml");
    const std::string kind = lrchain::jobs::experiment_kind(doc);
    if (kind == "drive") lrchain::jobs::load_drive_config(doc);
    else if (kind == "modulated") lrchain::jobs::load_modulated_config(doc);
    else lrchain::jobs::load_experiment_config(doc);
  } catch (const lrchain::InputError&) {
    // bad input, reported as such: exit 2 in the CLI
  }
  return 0;
}

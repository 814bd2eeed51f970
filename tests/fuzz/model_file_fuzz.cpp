// libFuzzer entry point for the model-file reader: the bytes are a model file's text (docs/models.md),
// read the way `lrchain derive --model` reads it (TOML, parameters and ranges, force laws parsed by
// GiNaC, fields, the checks of docs/models.md) and then evaluated at the defaults. Refusing the
// input with an InputError is the expected outcome; anything else (a crash, another exception, a
// sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "lrchain/derivation/model_file.hpp"
#include "lrchain/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto model = lrchain::derivation::parse_model_text(text, "fuzz.toml");
    lrchain::derivation::parameter_values(model, {});
  } catch (const lrchain::InputError&) {
    // bad input, reported as such: exit 2 in the CLI
  }
  return 0;
}

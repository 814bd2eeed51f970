// The user-model cache key (model_compiler.hpp): a SHA-256 (64 hex digits) that changes with the
// file's bytes, the compiler, the lrchain version and the kind of emitted code, so a cached shared
// object is never reused across any; its fields are length-prefixed, so moving bytes from one field
// to the next changes it too.
#include <doctest/doctest.h>

#include <string>

#include "lrchain/model_compiler.hpp"

using namespace lrchain;

TEST_CASE("the model cache key depends on the file, the compiler, the lrchain version and the emitter") {
  const std::string bytes = "name = \"x\"\n", compiler = "/usr/bin/c++", version = model_compiler_version();
  const auto key = model_cache_key(bytes, compiler, version, compiled_model_code_kind());
  CHECK(key == model_cache_key(bytes, compiler, version, compiled_model_code_kind()));  // deterministic
  CHECK(key != model_cache_key(bytes + " ", compiler, version, compiled_model_code_kind()));
  CHECK(key != model_cache_key(bytes, "/usr/bin/clang++", version, compiled_model_code_kind()));
  CHECK(key != model_cache_key(bytes, compiler, version + ".1", compiled_model_code_kind()));
  CHECK(key != model_cache_key(bytes, compiler, version, "evaluators 4"));  // the evaluators' own object before ABI 4
  CHECK(!version.empty());
  CHECK(key.size() == 64);
  CHECK(key.find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(model_cache_key("ab", "c", version, compiled_model_code_kind()) != model_cache_key("a", "bc", version, compiled_model_code_kind()));
}

TEST_CASE("the compiled model's cache entry names the ABI version of lrchain/compiled_model_abi.h") {
  // Before ABI 4 the evaluators ("evaluators 4") and the kernels ("lattice 3") were two objects:
  // their entries must never be loaded as the one object of ABI 4.
  CHECK(compiled_model_code_kind() == "compiled model " + std::to_string(LRCHAIN_COMPILED_MODEL_ABI_VERSION));
  CHECK(LRCHAIN_COMPILED_MODEL_ABI_VERSION >= 4);
  const std::string bytes = "name = \"x\"\n", compiler = "/usr/bin/c++", version = model_compiler_version();
  const std::string key = model_cache_key(bytes, compiler, version, compiled_model_code_kind());
  CHECK(key != model_cache_key(bytes, compiler, version, "lattice 3"));
  CHECK(key != model_cache_key(bytes, compiler, version, "evaluators 4"));
}

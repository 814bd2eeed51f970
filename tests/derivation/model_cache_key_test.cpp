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
  const auto key = model_cache_key(bytes, compiler, version, kEvaluatorCode);
  CHECK(key == model_cache_key(bytes, compiler, version, kEvaluatorCode));  // deterministic
  CHECK(key != model_cache_key(bytes + " ", compiler, version, kEvaluatorCode));
  CHECK(key != model_cache_key(bytes, "/usr/bin/clang++", version, kEvaluatorCode));
  CHECK(key != model_cache_key(bytes, compiler, version + ".1", kEvaluatorCode));
  CHECK(key != model_cache_key(bytes, compiler, version, "evaluators 2"));  // the emitter before harmonics()
  CHECK(!version.empty());
  CHECK(key.size() == 64);
  CHECK(key.find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(model_cache_key("ab", "c", version, kEvaluatorCode) != model_cache_key("a", "bc", version, kEvaluatorCode));
}

TEST_CASE("the lattice code's cache entry names the kernel table's ABI version") {
  // ABI version 1 had no contact tables: its cached libraries must be compiled again, not loaded.
  CHECK(lattice_code_kind() == "lattice " + std::to_string(LRCHAIN_LATTICE_ABI_VERSION));
  CHECK(LRCHAIN_LATTICE_ABI_VERSION >= 2);
  const std::string bytes = "name = \"x\"\n", compiler = "/usr/bin/c++", version = model_compiler_version();
  CHECK(model_cache_key(bytes, compiler, version, lattice_code_kind()) != model_cache_key(bytes, compiler, version, "lattice 1"));
}

// The committed lattice kernels of the shipped models (sim/src/model_lattice/generated) are what
// the generator writes today (no drift), and the kernel table in every generated file is the
// sim header's definition byte for byte.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lrchain/derivation/lattice_codegen.hpp"
#include "lrchain/derivation/model_file.hpp"

namespace {
std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("lattice codegen: committed kernels of every shipped model equal the generator's output" * doctest::test_suite("fast")) {
  const std::filesystem::path source(LRCHAIN_SOURCE_DIR);
  int models = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source / "models")) {
    if (entry.path().extension() != ".toml") continue;
    CAPTURE(entry.path().string());
    const lrchain::derivation::ModelFile model = lrchain::derivation::load_model_file(entry.path());
    const std::string generated = lrchain::derivation::lattice_source(model);
    const std::string committed = read(source / "sim/src/model_lattice/generated" / (entry.path().stem().string() + ".cpp"));
    CHECK(generated == committed);
    CHECK(committed.find(read(source / "lib/include/lrchain/compiled_model_abi.h")) != std::string::npos);
    ++models;
  }
  CHECK(models == 7);
}

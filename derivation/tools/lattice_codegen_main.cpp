// lrchain-lattice-codegen MODEL.toml OUT.cpp: writes the model's lattice kernels (lattice_codegen.hpp).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>

#include "lrchain/derivation/lattice_codegen.hpp"
#include "lrchain/derivation/model_file.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: lrchain-lattice-codegen MODEL.toml OUT.cpp\n");
    return 2;
  }
  try {
    const std::string text = lrchain::derivation::lattice_source(lrchain::derivation::load_model_file(argv[1]));
    const std::filesystem::path out(argv[2]), temporary(std::string(argv[2]) + ".tmp");
    {
      std::ofstream os(temporary, std::ios::binary);
      os << text;
      if (!os) throw std::runtime_error("cannot write " + temporary.string());
    }
    std::filesystem::rename(temporary, out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lrchain-lattice-codegen: %s\n", e.what());
    return 2;
  }
  return 0;
}

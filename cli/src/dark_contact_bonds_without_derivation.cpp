// One-sided contacts of a model file in a build without the derivation (LRCHAIN_BUILD_DERIVATION=OFF):
// reading a contact's overlap needs GiNaC's parser (dark_contact_bonds.cpp), so a model file that
// declares one is refused and a smooth model has none (dark_contact_bonds.hpp).
#include <toml++/toml.h>

#include "dark_contact_bonds.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::cli {

sim::dark::ContactBonds model_contact_bonds(const std::string& file, const Model&, bool) {
  toml::table root;
  try {
    root = toml::parse_file(file);
  } catch (const toml::parse_error& e) {
    throw InputError(file + ": " + std::string(e.description()));
  }
  if (const toml::table* functions = root["functions"].as_table())
    for (const auto& [name, law] : *functions)
      if (const toml::table* t = law.as_table(); t && t->contains("contact"))
        throw InputError(file + ": function " + std::string(name.str()) +
                         " has a one-sided contact; locating its contact changes needs lrchain built with the "
                         "derivation (cmake -DLRCHAIN_BUILD_DERIVATION=ON, Debian package libginac-dev)");
  return {};
}

}  // namespace lrchain::cli

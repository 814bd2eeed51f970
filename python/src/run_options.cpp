// Dict of run options -> fields of a C++ run config (run_options.hpp).
#include "run_options.hpp"

#include <pybind11/stl.h>

#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "real_numbers.hpp"

namespace py = pybind11;

namespace lrchain::python {

namespace {
// What a field takes, for the message of a value of the wrong type.
template <class T>
const char* type_name() {
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) return "a number";
  else if constexpr (std::is_same_v<T, long> || std::is_same_v<T, std::size_t>) return "an integer";
  else if constexpr (std::is_same_v<T, bool>) return "True or False";
  else if constexpr (std::is_same_v<T, std::vector<double>>) return "a sequence of numbers";
  else if constexpr (std::is_same_v<T, Params>) return "an lrchain.Params";
  else return "a string";
}
}  // namespace

void assign_options(const py::dict& options, const std::map<std::string, OptionTarget>& targets,
                    const char* function, const std::vector<config::RenamedKey>& renamed) {
  for (auto [key, value] : options) {
    const std::string name = py::str(key);
    const auto it = targets.find(name);
    for (const auto& r : renamed)
      if (it == targets.end() && name == r.old_name)
        throw py::type_error(std::string(function) + "() got the option '" + name + "', which is now " + r.replacement());
    if (it == targets.end()) {
      std::string allowed;
      for (const auto& [k, target] : targets) allowed += (allowed.empty() ? "" : ", ") + k;
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name +
                           "' (allowed: " + allowed + ")");
    }
    refuse_complex(value, name);  // never truncated to its real part
    std::visit(
        [&](auto* field) {
          using T = std::remove_pointer_t<decltype(field)>;
          try {
            if constexpr (std::is_same_v<T, Branch>) *field = parse_branch(value.cast<std::string>());
            else if constexpr (std::is_same_v<T, sim::StepperKind>) *field = sim::parse_stepper(value.cast<std::string>());
            else if constexpr (std::is_same_v<T, std::optional<double>>) *field = value.is_none() ? std::nullopt : std::optional(value.cast<double>());
            else *field = value.cast<T>();
          } catch (const py::cast_error&) {
            throw InvalidParameter(name, std::string("must be ") + type_name<T>() + ", not " +
                                             std::string(py::str(value.get_type().attr("__name__"))));
          }
        },
        it->second);
  }
}

}  // namespace lrchain::python

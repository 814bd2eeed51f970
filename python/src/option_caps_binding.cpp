// _lrchain.option_caps(): the caps of the integer options shared with the `lrchain` command, read
// from the one table of lrchain/config/option_caps.hpp (the tests refuse cap * 10 through both).
#include <string>
#include <tuple>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "lrchain/config/option_caps.hpp"

namespace py = pybind11;

namespace lrchain::python {

void register_option_caps(py::module_& m) {
  m.def(
      "option_caps",
      [] {
        std::vector<std::tuple<std::string, std::string, std::int64_t, std::int64_t, std::string, std::string>> out;
        for (const auto& c : config::option_caps())
          out.emplace_back(c.command, c.option, c.least, c.most, c.counted, c.python);
        return out;
      },
      "The caps of the integer options the lrchain command shares, as (command, option, least, most, "
      "counted unit or '', 'python_function keyword') tuples: Python refuses what the command refuses.");
}

}  // namespace lrchain::python

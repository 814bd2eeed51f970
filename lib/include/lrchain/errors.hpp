#pragma once
// Typed errors of the numeric library. The CLI maps InvalidParameter to exit code 2.
#include <stdexcept>
#include <string>

namespace lrchain {

// Invalid user input: the message names the parameter and its valid range.
class InvalidParameter : public std::invalid_argument {
 public:
  InvalidParameter(const std::string& parameter, const std::string& message)
      : std::invalid_argument(parameter + ": " + message), parameter_(parameter) {}
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

}  // namespace lrchain

#pragma once
// Typed errors of the library and their exit codes (exit_codes.hpp): the CLI maps each type to one
// code and prints what() as one line on stderr.
#include <stdexcept>
#include <string>

namespace lrchain {

// Bad user input (option, config key, file): exit code 2, nothing written. what() is the whole
// one-line message, naming the option, key or file and what is allowed.
class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& message) : std::invalid_argument(message) {}
};

// Invalid value of a named parameter: the message names the parameter and its valid range.
class InvalidParameter : public InputError {
 public:
  InvalidParameter(const std::string& parameter, const std::string& message)
      : InputError("invalid " + parameter + ": " + message), parameter_(parameter) {}
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

// A computation that failed for numerical reasons the user should know about (blow-up, Newton not
// converging): exit code 3; the JSON summary, where one is written, says so too.
class NumericalFailure : public std::runtime_error {
 public:
  explicit NumericalFailure(const std::string& message) : std::runtime_error(message) {}
};

// A run stopped by SIGINT or SIGTERM after writing its checkpoint and outputs: exit 128 + signal.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal_number, const std::string& message)
      : std::runtime_error(message), signal_(signal_number) {}
  int signal_number() const noexcept { return signal_; }

 private:
  int signal_;
};

}  // namespace lrchain

#pragma once
// The exit codes of every lrchain program (documented in the README and `lrchain --help`).
namespace lrchain::exit_code {

inline constexpr int success = 0;
inline constexpr int runtime_error = 1;      // I/O failure or another error that is not the input's
inline constexpr int invalid_input = 2;      // bad option, config key, file: nothing written
inline constexpr int numerical_failure = 3;  // blow-up, Newton not converging (also in the JSON)
inline constexpr int interrupted_base = 128; // + signal: 130 SIGINT, 143 SIGTERM (checkpoint written)

}  // namespace lrchain::exit_code

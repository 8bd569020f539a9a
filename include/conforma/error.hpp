#pragma once
// Errors for bad input. Degenerate physics (no contact, B <= 0 for Hertz, a fully sliding patch) is NOT an
// error: solvers report it through a status in their Result. Bad input (malformed files, NaN, negative load,
// unknown options) throws InputError with a message naming what and where.
#include <stdexcept>
#include <string>

namespace conforma {

class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& what) : std::invalid_argument(what) {}
  // "<where>:<line>: <what>" (line omitted when 0), the form compilers use, so editors can jump to it.
  InputError(const std::string& where, int line, const std::string& what)
      : std::invalid_argument(where + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what) {}
};

// A number in a message as "%g" prints it (1e+09, 1435, 0.0325): what the user gave, not std::to_string's 6 decimals
// (a 300-digit 1e300, 0.000000 for 1e-9). significant_digits: "%.<n>g" where 6 would hide the difference named.
std::string MessageNumber(double value, int significant_digits = 6);

// Throws InputError("<name> must be finite ...") unless value is finite.
void require_finite(double value, const char* name);
// Throws InputError unless value is finite and > 0.
void require_positive(double value, const char* name);
// Throws InputError unless value is finite and >= 0.
void require_non_negative(double value, const char* name);

}  // namespace conforma

#include "conforma/error.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace conforma {

std::string MessageNumber(double value, int significant_digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", significant_digits, value);
  return text;
}

namespace {
std::string describe(const char* name, double value, const char* rule) {
  std::ostringstream out;
  out << "parameter '" << name << "' = " << value << " must be " << rule;
  return out.str();
}
}  // namespace

void require_finite(double value, const char* name) {
  if (!std::isfinite(value)) throw InputError(describe(name, value, "finite"));
}

void require_positive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0) throw InputError(describe(name, value, "finite and > 0"));
}

void require_non_negative(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) throw InputError(describe(name, value, "finite and >= 0"));
}

}  // namespace conforma

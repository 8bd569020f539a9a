#pragma once
// One number as text with a printf format (e.g. "%.4f", "%g"): the reports' and tables' number formatting.
#include <cstdio>
#include <string>

namespace conforma::cli {

inline std::string Fmt(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

}  // namespace conforma::cli

#pragma once
// The C API's mapping of a C++ exception to its status and text (conforma_c.cpp, conforma_c_rig.cpp): every entry
// point catches everything and returns this.
#include <exception>
#include <string>

#include "conforma/error.hpp"
#include "conforma_c.h"
#include "interop.hpp"

namespace conforma::capi {

// Call inside a catch block only: CONFORMA_ERROR_INPUT with the message for an InputError, CONFORMA_ERROR_INTERNAL
// with "internal error: ..." for any other exception (and "internal error" for a non-standard one).
inline conforma_status CurrentExceptionStatus(std::string* message) {
  try {
    throw;
  } catch (const conforma::InputError& e) {
    *message = e.what();
    return CONFORMA_ERROR_INPUT;
  } catch (const std::exception& e) {
    *message = std::string("internal error: ") + e.what();
  } catch (...) {
    *message = "internal error";
  }
  return CONFORMA_ERROR_INTERNAL;
}

// Call inside a catch block only: the status above, its text copied into the caller's buffer (interop::CopyText).
inline conforma_status ReportCurrentException(char* buffer, size_t size) {
  std::string message;
  const conforma_status status = CurrentExceptionStatus(&message);
  interop::CopyText(message, buffer, size);
  return status;
}

}  // namespace conforma::capi

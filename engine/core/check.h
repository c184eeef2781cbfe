#pragma once
// Internal invariants. DIPTYCH_CHECK(cond, message) is for what our own code guarantees (a
// table lookup by an id we created, a handle in range); it throws InternalError naming the
// source place, the expression and what broke. Problems in user input are InputError instead
// (engine/core/error.h). The check stays on in release builds: a broken invariant must be a
// clear error, never an anonymous std::out_of_range from .at() or undefined behaviour.
#include <string>

#include "engine/core/error.h"

namespace diptych {

// what() reads "internal error: FILE:LINE: check 'EXPRESSION' failed: MESSAGE".
class InternalError : public Error {
 public:
  using Error::Error;
};

[[noreturn]] void failCheck(const char* file, int line, const char* expression,
                            const std::string& message);

}  // namespace diptych

#define DIPTYCH_CHECK(cond, message)                                              \
  do {                                                                            \
    if (!(cond)) [[unlikely]]                                                     \
      ::diptych::failCheck(__FILE__, __LINE__, #cond, std::string() + (message)); \
  } while (false)

#include "engine/core/error.h"

#include <cstdio>

namespace sb {

Error make_error_v(const char* fmt, va_list args) {
  Error e;
  std::vsnprintf(e.message, sizeof e.message, fmt, args);
  return e;
}

Error make_error(const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  Error e = make_error_v(fmt, args);
  va_end(args);
  return e;
}

}  // namespace sb

// engine/core/error.h: failures as values.
//
// No exceptions in the engine. A function that can fail returns Status (no value)
// or Result<T>. The message names the file, lump, offset or field, e.g.
//   "maps/start.bsp: lump 'faces' (offset 1234, length 99): length is not a multiple of 20"
// Messages live in a fixed 256-byte buffer: no heap.
#pragma once
#include <cstdarg>
#include <cstddef>
#include <utility>

namespace sb {

struct Error {
  char message[256] = {};
};

Error make_error(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
Error make_error_v(const char* fmt, va_list args);

class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(const Error& e) : ok_(false), error_(e) {}  // NOLINT: implicit by design
  static Status ok() { return Status(); }
  bool is_ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const Error& error() const { return error_; }
  const char* message() const { return ok_ ? "ok" : error_.message; }

 private:
  bool ok_ = true;
  Error error_;
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(const T& v) : ok_(true), value_(v) {}     // NOLINT
  Result(T&& v) : ok_(true), value_(std::move(v)) {}  // NOLINT
  Result(const Error& e) : ok_(false), error_(e) {}  // NOLINT
  bool is_ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  T& value() { return value_; }
  const T& value() const { return value_; }
  T* operator->() { return &value_; }
  const Error& error() const { return error_; }
  const char* message() const { return ok_ ? "ok" : error_.message; }
  Status status() const { return ok_ ? Status() : Status(error_); }

 private:
  bool ok_;
  T value_{};
  Error error_;
};

#define SB_TRY(expr)                              \
  do {                                            \
    ::sb::Status sb_try_status_ = (expr);         \
    if (!sb_try_status_) return sb_try_status_.error(); \
  } while (0)

}  // namespace sb

// engine/host/console.h: the command buffer, command table and cvar table.
//
//   text in ("map start; viewpos 0 0 64 90 0\nquit")
//        |
//   [ command buffer: fixed char array ] --execute()--> one line at a time
//        |                                               |
//        |                         tokenize -> argv[0] names a command or a cvar
//        |                                               |
//   wait requested? stop, keep the rest for the next execute()   run it
//
// Lines end at '\n' or at a ';' outside double quotes. Tokens are separated by
// blanks; "double quotes" group a token; "//" starts a comment to the end of line.
// A line naming a cvar with no argument prints it, with an argument sets it.
//
// Memory: every table and the buffer come from the arena given to init()
// (the permanent arena); nothing here touches the heap. Capacities are fixed at
// init: registering past them or appending past the buffer fails with a Status.
// Lifetime: names and help texts passed in must be static strings.
#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/core/error.h"
#include "memory/arena.h"

namespace sb::host {

constexpr int kMaxArgs = 16;
constexpr int kMaxLineChars = 256;  // longer lines are rejected with a message

// One tokenized line. argv points into storage (no heap).
struct CommandArgs {
  int argc = 0;
  const char* argv[kMaxArgs] = {};
  char storage[kMaxLineChars + kMaxArgs] = {};

  const char* arg(int i) const { return i < argc ? argv[i] : ""; }
};

// Splits one line into tokens. Fails (message names the line) when the line is
// too long, has too many tokens or an unterminated quote.
Status tokenize(const char* line, CommandArgs* out);

using CommandFn = void (*)(void* user, const CommandArgs& args);
using CvarChanged = void (*)(void* user, const struct Cvar& cvar);

struct Cvar {
  static constexpr int kMaxString = 64;
  const char* name = nullptr;  // static string
  const char* help = nullptr;  // static string
  char string[kMaxString] = {};
  float value = 0.0f;          // strtof(string), 0 when not a number
  CvarChanged changed = nullptr;
  void* user = nullptr;
};

class Console {
 public:
  // Tables for max_commands commands and max_cvars cvars, and a command buffer of
  // buffer_chars characters, all pushed on `arena`.
  Status init(mem::Arena& arena, int max_commands, int max_cvars, size_t buffer_chars);

  Status add_command(const char* name, CommandFn fn, void* user, const char* help);
  // Registers (or returns the existing) cvar. nullptr when the table is full.
  Cvar* add_cvar(const char* name, const char* default_value, const char* help,
                 CvarChanged changed = nullptr, void* user = nullptr);
  Cvar* find_cvar(const char* name);
  void set_cvar(Cvar& cvar, const char* value);  // calls the change hook

  // Appends text at the end of the buffer (a line break is added when missing).
  Status append(const char* text);
  // Inserts text before everything still waiting in the buffer.
  Status insert(const char* text);
  // Runs buffered lines until the buffer is empty or a command called wait().
  void execute();
  // Runs one line now, bypassing the buffer.
  void execute_line(const char* line);
  // Stops execute() after the current line; the rest waits for the next execute().
  void wait() { waiting_ = true; }
  bool empty() const { return used_ == 0; }
  size_t buffered_chars() const { return used_; }

  // Help lines for every command and cvar ("name - help").
  void list(void (*line)(void* user, const char* text), void* user) const;

 private:
  struct Command {
    const char* name;
    const char* help;
    CommandFn fn;
    void* user;
  };
  const Command* find_command(const char* name) const;
  size_t next_line(char* out, size_t out_size, bool* too_long);

  Command* commands_ = nullptr;
  int num_commands_ = 0, max_commands_ = 0;
  Cvar* cvars_ = nullptr;
  int num_cvars_ = 0, max_cvars_ = 0;
  char* buffer_ = nullptr;
  size_t used_ = 0, capacity_ = 0;
  bool waiting_ = false;
};

}  // namespace sb::host

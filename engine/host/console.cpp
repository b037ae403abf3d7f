#include "engine/host/console.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "engine/core/log.h"

namespace sb::host {

Status tokenize(const char* line, CommandArgs* out) {
  out->argc = 0;
  size_t len = std::strlen(line);
  if (len > kMaxLineChars) return make_error("console: line of %zu characters is longer than %d", len, kMaxLineChars);
  char* w = out->storage;
  const char* p = line;
  while (true) {
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
    if (!*p || (p[0] == '/' && p[1] == '/')) break;
    if (out->argc == kMaxArgs) return make_error("console: more than %d tokens in \"%.40s\"", kMaxArgs, line);
    out->argv[out->argc++] = w;
    if (*p == '"') {
      ++p;
      while (*p && *p != '"') *w++ = *p++;
      if (*p != '"') return make_error("console: unterminated quote in \"%.40s\"", line);
      ++p;
    } else {
      while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') *w++ = *p++;
    }
    *w++ = '\0';  // storage holds len + one terminator per token: never overflows
  }
  return Status::ok();
}

Status Console::init(mem::Arena& arena, int max_commands, int max_cvars, size_t buffer_chars) {
  commands_ = arena.push_array<Command>(size_t(max_commands), "console commands");
  cvars_ = arena.push_array<Cvar>(size_t(max_cvars), "console cvars");
  buffer_ = arena.push_array<char>(buffer_chars + 1, "console command buffer");
  if (!commands_ || !cvars_ || !buffer_) {
    Error e;
    arena.failure_message(e.message, sizeof e.message);
    return e;
  }
  max_commands_ = max_commands;
  max_cvars_ = max_cvars;
  capacity_ = buffer_chars;
  num_commands_ = num_cvars_ = 0;
  used_ = 0;
  waiting_ = false;
  return Status::ok();
}

const Console::Command* Console::find_command(const char* name) const {
  for (int i = 0; i < num_commands_; ++i)
    if (std::strcmp(commands_[i].name, name) == 0) return &commands_[i];
  return nullptr;
}

Cvar* Console::find_cvar(const char* name) {
  for (int i = 0; i < num_cvars_; ++i)
    if (std::strcmp(cvars_[i].name, name) == 0) return &cvars_[i];
  return nullptr;
}

Status Console::add_command(const char* name, CommandFn fn, void* user, const char* help) {
  if (find_command(name) || find_cvar(name)) return make_error("console: '%s' is already registered", name);
  if (num_commands_ == max_commands_)
    return make_error("console: command table is full (%d) adding '%s'", max_commands_, name);
  commands_[num_commands_++] = Command{name, help, fn, user};
  return Status::ok();
}

Cvar* Console::add_cvar(const char* name, const char* default_value, const char* help, CvarChanged changed,
                        void* user) {
  if (Cvar* existing = find_cvar(name)) return existing;
  if (num_cvars_ == max_cvars_ || find_command(name)) return nullptr;
  Cvar& c = cvars_[num_cvars_++];
  c.name = name;
  c.help = help;
  c.changed = nullptr;  // no hook while setting the default
  set_cvar(c, default_value);
  c.changed = changed;
  c.user = user;
  return &c;
}

void Console::set_cvar(Cvar& cvar, const char* value) {
  std::strncpy(cvar.string, value, Cvar::kMaxString - 1);
  cvar.string[Cvar::kMaxString - 1] = '\0';
  cvar.value = std::strtof(cvar.string, nullptr);
  if (cvar.changed) cvar.changed(cvar.user, cvar);
}

Status Console::append(const char* text) {
  size_t len = std::strlen(text);
  bool needs_break = len == 0 || text[len - 1] != '\n';
  if (used_ + len + (needs_break ? 1 : 0) > capacity_)
    return make_error("console: command buffer full (%zu of %zu characters) appending \"%.40s\"", used_, capacity_,
                      text);
  std::memcpy(buffer_ + used_, text, len);
  used_ += len;
  if (needs_break) buffer_[used_++] = '\n';
  buffer_[used_] = '\0';
  return Status::ok();
}

Status Console::insert(const char* text) {
  size_t len = std::strlen(text);
  bool needs_break = len == 0 || text[len - 1] != '\n';
  size_t add = len + (needs_break ? 1 : 0);
  if (used_ + add > capacity_)
    return make_error("console: command buffer full (%zu of %zu characters) inserting \"%.40s\"", used_, capacity_,
                      text);
  std::memmove(buffer_ + add, buffer_, used_);
  std::memcpy(buffer_, text, len);
  if (needs_break) buffer_[len] = '\n';
  used_ += add;
  buffer_[used_] = '\0';
  return Status::ok();
}

// Takes the first line out of the buffer into out. Returns its length.
size_t Console::next_line(char* out, size_t out_size, bool* too_long) {
  size_t end = 0;
  bool quoted = false;
  while (end < used_) {
    char c = buffer_[end];
    if (c == '"') quoted = !quoted;
    if (c == '\n' || (c == ';' && !quoted)) break;
    ++end;
  }
  *too_long = end >= out_size;
  size_t n = *too_long ? out_size - 1 : end;
  std::memcpy(out, buffer_, n);
  out[n] = '\0';
  size_t consumed = end < used_ ? end + 1 : end;
  std::memmove(buffer_, buffer_ + consumed, used_ - consumed);
  used_ -= consumed;
  buffer_[used_] = '\0';
  return n;
}

void Console::execute() {
  waiting_ = false;
  char line[kMaxLineChars + 2];
  while (used_ > 0 && !waiting_) {
    bool too_long = false;
    next_line(line, sizeof line, &too_long);
    if (too_long) {
      log_error("console: line longer than %d characters ignored: \"%.40s...\"", kMaxLineChars, line);
      continue;
    }
    execute_line(line);
  }
}

void Console::execute_line(const char* line) {
  CommandArgs args;
  Status s = tokenize(line, &args);
  if (!s) {
    log_error("%s", s.message());
    return;
  }
  if (args.argc == 0) return;
  if (const Command* c = find_command(args.argv[0])) {
    c->fn(c->user, args);
    return;
  }
  if (Cvar* v = find_cvar(args.argv[0])) {
    if (args.argc == 1)
      log_info("\"%s\" is \"%s\"", v->name, v->string);
    else
      set_cvar(*v, args.argv[1]);
    return;
  }
  log_error("unknown command \"%s\" (type 'help' for the list)", args.argv[0]);
}

void Console::list(void (*line)(void* user, const char* text), void* user) const {
  char buf[160];
  for (int i = 0; i < num_commands_; ++i) {
    std::snprintf(buf, sizeof buf, "  %-12s %s", commands_[i].name, commands_[i].help ? commands_[i].help : "");
    line(user, buf);
  }
  for (int i = 0; i < num_cvars_; ++i) {
    std::snprintf(buf, sizeof buf, "  %-12s %s (cvar, now \"%s\")", cvars_[i].name,
                  cvars_[i].help ? cvars_[i].help : "", cvars_[i].string);
    line(user, buf);
  }
}

}  // namespace sb::host

// tools/bsp/map_file.cpp: see map_file.h.
#include "tools/bsp/map_file.h"

#include <charconv>
#include <cstdio>

namespace sb::tools::bsp {

const std::string* MapEntity::find(std::string_view key) const {
  for (const auto& kv : pairs)
    if (kv.first == key) return &kv.second;
  return nullptr;
}

void MapEntity::set(std::string_view key, std::string_view value) {
  for (auto& kv : pairs)
    if (kv.first == key) {
      kv.second = std::string(value);
      return;
    }
  pairs.emplace_back(std::string(key), std::string(value));
}

bool read_file(const char* path, std::string* out) {
  FILE* f = std::fopen(path, "rb");
  if (!f) return false;
  out->clear();
  char buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out->append(buf, n);
  bool ok = !std::ferror(f);
  std::fclose(f);
  return ok;
}

namespace {

// Cursor over the text with line tracking.
class Lexer {
 public:
  Lexer(const char* name, std::string_view text) : name_(name), t_(text) {}

  int line() const { return line_; }

  // Skips whitespace and comments. Returns false at the end of the text.
  bool skip(bool stop_at_newline = false) {
    while (pos_ < t_.size()) {
      char c = t_[pos_];
      if (c == '\n') {
        if (stop_at_newline) return true;
        ++line_;
        ++pos_;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++pos_;
      } else if (c == '/' && pos_ + 1 < t_.size() && t_[pos_ + 1] == '/') {
        while (pos_ < t_.size() && t_[pos_] != '\n') ++pos_;
      } else {
        return true;
      }
    }
    return false;
  }
  bool at_line_end() {
    skip(true);
    return pos_ >= t_.size() || t_[pos_] == '\n';
  }
  char peek() { return skip() ? t_[pos_] : '\0'; }

  // A quoted string (no escapes).
  Status quoted(std::string* out) {
    if (peek() != '"') return err("expected '\"'");
    size_t start = ++pos_;
    int start_line = line_;
    while (pos_ < t_.size() && t_[pos_] != '"') {
      if (t_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= t_.size()) return make_error("%s:%d: unterminated quoted string", name_, start_line);
    out->assign(t_.substr(start, pos_ - start));
    ++pos_;
    return Status::ok();
  }
  // A bare word up to whitespace (texture names may contain any other byte); a quoted
  // word is accepted too.
  Status word(std::string* out, const char* what) {
    char c = peek();
    if (c == '\0') return err("unexpected end of file, expected %s", what);
    if (c == '"') return quoted(out);
    size_t start = pos_;
    while (pos_ < t_.size() && !is_space(t_[pos_])) ++pos_;
    out->assign(t_.substr(start, pos_ - start));
    return Status::ok();
  }
  Status expect(char c) {
    char p = peek();
    if (p != c) {
      if (p == '\0') return err("unexpected end of file, expected '%c'", c);
      return err("expected '%c', found '%c'", c, p);
    }
    ++pos_;
    return Status::ok();
  }
  Status number(double* out, const char* what) {
    char c = peek();
    if (c == '\0') return err("unexpected end of file, expected %s", what);
    size_t start = pos_;
    while (pos_ < t_.size() && !is_space(t_[pos_]) && t_[pos_] != ')' && t_[pos_] != ']' && t_[pos_] != '(' &&
           t_[pos_] != '[')
      ++pos_;
    std::string_view s = t_.substr(start, pos_ - start);
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    double v = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size()) {
      if (s.empty()) return err("expected %s, found '%c'", what, c);
      return err("expected %s, found '%.*s'", what, int(std::min<size_t>(s.size(), 40)), s.data());
    }
    *out = v;
    return Status::ok();
  }
  bool next_is_number() {
    char c = peek();
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
  }
  Error err(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
    char msg[200];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return make_error("%s:%d: %s", name_, line_, msg);
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  const char* name_;
  std::string_view t_;
  size_t pos_ = 0;
  int line_ = 1;
};

Status parse_vec(Lexer& lx, Vec3* v, char open, char close, double* fourth) {
  SB_TRY(lx.expect(open));
  for (int i = 0; i < 3; ++i) SB_TRY(lx.number(&(*v)[i], "a coordinate"));
  if (fourth) SB_TRY(lx.number(fourth, "a texture offset"));
  return lx.expect(close);
}

Status parse_face(Lexer& lx, MapFile* map, MapFace* f) {
  f->line = lx.line();
  for (Vec3& p : f->points) SB_TRY(parse_vec(lx, &p, '(', ')', nullptr));
  SB_TRY(lx.word(&f->texture, "a texture name"));
  if (f->texture.size() > 15) {
    map->warnings.push_back(std::string(map->path) + ":" + std::to_string(f->line) + ": texture name '" + f->texture +
                            "' is longer than 15 characters: cut to '" + f->texture.substr(0, 15) + "'");
    f->texture.resize(15);
  }
  if (lx.peek() == '[') {
    f->valve = true;
    SB_TRY(parse_vec(lx, &f->axis[0], '[', ']', &f->shift[0]));
    SB_TRY(parse_vec(lx, &f->axis[1], '[', ']', &f->shift[1]));
    map->valve_faces++;
  } else {
    SB_TRY(lx.number(&f->shift[0], "a texture x offset"));
    SB_TRY(lx.number(&f->shift[1], "a texture y offset"));
    map->standard_faces++;
  }
  SB_TRY(lx.number(&f->rotate, "a texture rotation"));
  SB_TRY(lx.number(&f->scale[0], "a texture x scale"));
  SB_TRY(lx.number(&f->scale[1], "a texture y scale"));
  // Extra values on the line (Quake 2 contents/flags/value): ignored.
  while (!lx.at_line_end() && lx.next_is_number()) {
    double ignored;
    SB_TRY(lx.number(&ignored, "a number"));
  }
  return Status::ok();
}

}  // namespace

Status parse_map(const char* name, std::string_view text, MapFile* out) {
  out->path = name;
  out->entities.clear();
  out->warnings.clear();
  Lexer lx(name, text);
  while (lx.peek() != '\0') {
    MapEntity e;
    e.line = lx.line();
    SB_TRY(lx.expect('{'));
    for (;;) {
      char c = lx.peek();
      if (c == '\0') return make_error("%s:%d: entity is not closed (missing '}')", name, e.line);
      if (c == '}') {
        SB_TRY(lx.expect('}'));
        break;
      }
      if (c == '"') {
        std::string k, v;
        SB_TRY(lx.quoted(&k));
        if (lx.peek() != '"') return lx.err("key \"%.40s\" has no value", k.c_str());
        SB_TRY(lx.quoted(&v));
        e.pairs.emplace_back(std::move(k), std::move(v));
      } else if (c == '{') {
        MapBrush b;
        b.line = lx.line();
        SB_TRY(lx.expect('{'));
        for (;;) {
          char d = lx.peek();
          if (d == '}') {
            SB_TRY(lx.expect('}'));
            break;
          }
          if (d == '\0') return make_error("%s:%d: brush is not closed (missing '}')", name, b.line);
          if (d != '(') {
            return lx.err("expected '(' starting a brush face or '}' (patches and brush primitives are not supported)");
          }
          MapFace f;
          SB_TRY(parse_face(lx, out, &f));
          b.faces.push_back(std::move(f));
        }
        e.brushes.push_back(std::move(b));
      } else {
        return lx.err("expected a \"key\", a brush '{' or '}', found '%c'", c);
      }
    }
    out->entities.push_back(std::move(e));
  }
  if (out->entities.empty()) return make_error("%s: no entities", name);
  if (out->entities[0].classname() != "worldspawn")
    return make_error("%s:%d: the first entity is not worldspawn", name, out->entities[0].line);
  return Status::ok();
}

Status read_map(const char* path, MapFile* out) {
  std::string text;
  if (!read_file(path, &text)) return make_error("%s: cannot read the file", path);
  return parse_map(path, text, out);
}

}  // namespace sb::tools::bsp

// engine/formats/entities.cpp: entity string tokenizer and helpers (no heap).
#include "engine/formats/entities.h"

#include <charconv>

namespace sb {
namespace {

enum class Tok { End, Word, Quoted, Open, Close, BadQuote };

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v' || c == 0; }

// Reads the token at *pos; on return *pos is past it. For Word/Quoted, *tok is
// its text (without quotes). For BadQuote, *pos is the opening quote's offset.
Tok next_token(std::string_view t, size_t* pos, std::string_view* tok) {
  size_t i = *pos;
  for (;;) {
    while (i < t.size() && is_space(t[i])) ++i;
    if (i + 1 < t.size() && t[i] == '/' && t[i + 1] == '/') {
      while (i < t.size() && t[i] != '\n') ++i;
      continue;
    }
    break;
  }
  if (i >= t.size()) {
    *pos = i;
    return Tok::End;
  }
  char c = t[i];
  if (c == '{' || c == '}') {
    *pos = i + 1;
    return c == '{' ? Tok::Open : Tok::Close;
  }
  if (c == '"') {
    size_t start = i + 1, end = start;
    while (end < t.size() && t[end] != '"') ++end;
    if (end >= t.size()) {
      *pos = i;
      return Tok::BadQuote;
    }
    *tok = t.substr(start, end - start);
    *pos = end + 1;
    return Tok::Quoted;
  }
  size_t start = i;
  while (i < t.size() && !is_space(t[i]) && t[i] != '{' && t[i] != '}' && t[i] != '"') ++i;
  *tok = t.substr(start, i - start);
  *pos = i;
  return Tok::Word;
}

}  // namespace

bool EntityIterator::next(Entity* out) {
  if (error_) return false;
  std::string_view tok;
  size_t p = pos_;
  Tok k = next_token(text_, &p, &tok);
  if (k == Tok::End) {
    pos_ = p;
    return false;
  }
  if (k != Tok::Open) {
    error_ = "expected '{' to start an entity";
    error_offset_ = pos_;
    return false;
  }
  size_t open = p - 1;
  for (;;) {
    k = next_token(text_, &p, &tok);
    if (k == Tok::Close) {
      out->body = text_.substr(open + 1, p - 1 - (open + 1));
      out->offset = open;
      pos_ = p;
      return true;
    }
    if (k == Tok::End) {
      error_ = "entity not closed by '}' before the end of the text";
      error_offset_ = open;
      return false;
    }
    if (k == Tok::BadQuote) {
      error_ = "unterminated quoted string";
      error_offset_ = p;
      return false;
    }
    if (k == Tok::Open) {
      error_ = "unexpected '{' inside an entity";
      error_offset_ = p - 1;
      return false;
    }
  }
}

bool Entity::next_pair(size_t* cursor, EntityPair* out) const {
  std::string_view key, value;
  size_t p = *cursor;
  Tok k = next_token(body, &p, &key);
  if (k != Tok::Word && k != Tok::Quoted) return false;
  Tok v = next_token(body, &p, &value);
  if (v != Tok::Word && v != Tok::Quoted) return false;
  *cursor = p;
  out->key = key;
  out->value = value;
  return true;
}

bool Entity::find(std::string_view key, std::string_view* value) const {
  size_t cursor = 0;
  EntityPair pair;
  while (next_pair(&cursor, &pair)) {
    if (pair.key == key) {
      *value = pair.value;
      return true;
    }
  }
  return false;
}

std::string_view Entity::classname() const {
  std::string_view v;
  return find("classname", &v) ? v : std::string_view();
}

bool find_entity(std::string_view text, std::string_view classname, Entity* out) {
  EntityIterator it(text);
  Entity e;
  while (it.next(&e)) {
    if (e.classname() == classname) {
      *out = e;
      return true;
    }
  }
  return false;
}

bool parse_float(std::string_view s, float* out) {
  size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  if (i < s.size() && s[i] == '+') ++i;
  const char* first = s.data() + i;
  const char* last = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(first, last, *out);
  if (ec != std::errc() || ptr == first) return false;
  for (; ptr < last; ++ptr)
    if (!is_space(*ptr)) return false;
  return true;
}

bool parse_vec3(std::string_view s, glm::vec3* out) {
  size_t i = 0;
  for (int k = 0; k < 3; ++k) {
    while (i < s.size() && is_space(s[i])) ++i;
    size_t start = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    if (start == i || !parse_float(s.substr(start, i - start), &(*out)[k])) return false;
  }
  while (i < s.size() && is_space(s[i])) ++i;
  return i == s.size();
}

bool entity_origin(const Entity& e, glm::vec3* out) {
  std::string_view v;
  return e.find("origin", &v) && parse_vec3(v, out);
}

bool entity_angles(const Entity& e, glm::vec3* pitch_yaw_roll) {
  std::string_view v;
  if (e.find("mangle", &v) && parse_vec3(v, pitch_yaw_roll)) return true;
  float angle = 0;
  if (!e.find("angle", &v) || !parse_float(v, &angle)) return false;
  if (angle == -1.0f)
    *pitch_yaw_roll = glm::vec3(-90.0f, 0.0f, 0.0f);
  else if (angle == -2.0f)
    *pitch_yaw_roll = glm::vec3(90.0f, 0.0f, 0.0f);
  else
    *pitch_yaw_roll = glm::vec3(0.0f, angle, 0.0f);
  return true;
}

}  // namespace sb

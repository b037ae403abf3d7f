// engine/formats/entities.h: the entity string of a BSP, read without allocating.
//
//   { "classname" "worldspawn" "wad" "gfx.wad" }
//   { "classname" "info_player_start" "origin" "480 -352 88" "angle" "90" }
//
// Tokens: whitespace separates; "// ..." comments run to the end of the line;
// a token is either a quoted string (no escapes; may contain any byte but '"',
// any length) or a bare word ending at whitespace, '{', '}' or '"'.
// Every view returned points into the caller's text, which must outlive it.
#pragma once
#include <cstddef>
#include <string_view>

#include <glm/vec3.hpp>

namespace sb {

struct EntityPair {
  std::string_view key, value;
};

// One entity: the text between its braces.
struct Entity {
  std::string_view body;
  size_t offset = 0;  // of the '{' in the whole text (for messages)

  // Walks the pairs: start with *cursor = 0; returns false after the last pair.
  // A key without a value ends the walk.
  bool next_pair(size_t* cursor, EntityPair* out) const;
  // Value of the first pair with this key (exact, case-sensitive), or false.
  bool find(std::string_view key, std::string_view* value) const;
  std::string_view classname() const;  // empty when absent
};

// Iterates the entities of a text. The text need not be NUL-terminated.
class EntityIterator {
 public:
  EntityIterator(const char* text, size_t size) : text_(text, size) {}
  explicit EntityIterator(std::string_view text) : text_(text) {}

  // Next entity; false at the end of the text or on a syntax error (then
  // error() describes it, e.g. "unterminated quoted string at offset 1234").
  bool next(Entity* out);
  const char* error() const { return error_; }
  size_t error_offset() const { return error_offset_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  const char* error_ = nullptr;
  size_t error_offset_ = 0;
};

// The first entity whose classname equals `classname`.
bool find_entity(std::string_view text, std::string_view classname, Entity* out);

// Number parsing (locale-independent). parse_vec3 reads three numbers separated by whitespace.
bool parse_float(std::string_view s, float* out);
bool parse_vec3(std::string_view s, glm::vec3* out);

// "origin" as a vec3.
bool entity_origin(const Entity& e, glm::vec3* out);
// View angles in degrees as (pitch, yaw, roll): "mangle" (pitch yaw roll) when
// present, else "angle" as yaw, where -1 means straight up (pitch -90) and -2
// straight down (pitch 90), Quake's convention. False when neither key exists.
bool entity_angles(const Entity& e, glm::vec3* pitch_yaw_roll);

}  // namespace sb

// tools/vis/prt.cpp: PRT1 text reader (see vis.h for the conventions).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "tools/vis/vis.h"

namespace sb::tools::vis {

namespace {

// A tiny cursor over the text that counts lines for messages.
struct Cursor {
  const char* p;
  const char* end;
  int line = 1;
  void skip_space() {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')) {
      if (*p == '\n') ++line;
      ++p;
    }
  }
  // Skips blanks on the current line only.
  void skip_blank() {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
  }
  bool number(double* v) {
    skip_blank();
    if (p >= end) return false;
    char buf[64];
    size_t n = 0;
    while (p + n < end && n < sizeof buf - 1 && std::strchr("+-.0123456789eE", p[n])) ++n;
    if (n == 0) return false;
    std::memcpy(buf, p, n);
    buf[n] = 0;
    char* e = nullptr;
    *v = std::strtod(buf, &e);
    if (e != buf + n || !std::isfinite(*v)) return false;
    p += n;
    return true;
  }
  bool integer(long* v) {
    double d;
    const char* start = p;
    if (!number(&d) || d != std::floor(d) || std::fabs(d) > 1e9) {
      p = start;
      return false;
    }
    *v = long(d);
    return true;
  }
  bool expect(char c) {
    skip_blank();
    if (p < end && *p == c) {
      ++p;
      return true;
    }
    return false;
  }
};

}  // namespace

Status parse_prt(const char* name, const std::string& text, PortalFile* out) {
  *out = PortalFile();
  Cursor c{text.data(), text.data() + text.size()};
  c.skip_space();
  if (size_t(c.end - c.p) < 4 || std::memcmp(c.p, "PRT1", 4) != 0)
    return make_error("%s: line %d: not a PRT1 portal file", name, c.line);
  c.p += 4;
  long leaves = 0, portals = 0;
  c.skip_space();
  if (!c.integer(&leaves) || leaves < 0 || leaves > 4000000)
    return make_error("%s: line %d: bad leaf count", name, c.line);
  c.skip_space();
  if (!c.integer(&portals) || portals < 0 || portals > 8000000)
    return make_error("%s: line %d: bad portal count", name, c.line);
  out->num_leaves = int(leaves);
  out->portals.resize(size_t(portals));
  for (long i = 0; i < portals; ++i) {
    c.skip_space();
    PrtPortal& pt = out->portals[size_t(i)];
    long n = 0, a = 0, b = 0;
    if (!c.integer(&n) || n < 3 || n > 1000) return make_error("%s: line %d: portal %ld: bad point count", name, c.line, i);
    if (!c.integer(&a) || !c.integer(&b) || a < 0 || b < 0 || a >= leaves || b >= leaves || a == b)
      return make_error("%s: line %d: portal %ld: bad leaf numbers", name, c.line, i);
    pt.leaf[0] = int(a);
    pt.leaf[1] = int(b);
    pt.points.resize(size_t(n) * 3);
    for (long k = 0; k < n; ++k) {
      if (!c.expect('(')) return make_error("%s: line %d: portal %ld: '(' expected", name, c.line, i);
      for (int j = 0; j < 3; ++j)
        if (!c.number(&pt.points[size_t(k * 3 + j)]))
          return make_error("%s: line %d: portal %ld: bad coordinate", name, c.line, i);
      if (!c.expect(')')) return make_error("%s: line %d: portal %ld: ')' expected", name, c.line, i);
    }
  }
  return Status::ok();
}

Status read_prt(const char* path, PortalFile* out) {
  FILE* f = std::fopen(path, "rb");
  if (!f) return make_error("%s: cannot open the portal file (run sbbsp first; a leaking map has none)", path);
  std::string text;
  char buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  bool err = std::ferror(f) != 0;
  std::fclose(f);
  if (err) return make_error("%s: read error", path);
  return parse_prt(path, text, out);
}

}  // namespace sb::tools::vis

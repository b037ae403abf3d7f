// tools/vis/prt.cpp: PRT1 / PRT2 text reader (see vis.h for the conventions).
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
  bool prt2 = false;
  if (size_t(c.end - c.p) >= 4 && std::memcmp(c.p, "PRT2", 4) == 0) prt2 = true;
  else if (size_t(c.end - c.p) < 4 || std::memcmp(c.p, "PRT1", 4) != 0)
    return make_error("%s: line %d: not a PRT1 or PRT2 portal file", name, c.line);
  c.p += 4;
  long leaves = 0, clusters = 0, portals = 0;
  c.skip_space();
  if (!c.integer(&leaves) || leaves < 0 || leaves > 4000000)
    return make_error("%s: line %d: bad leaf count", name, c.line);
  clusters = leaves;
  if (prt2) {
    c.skip_space();
    if (!c.integer(&clusters) || clusters < 0 || clusters > leaves)
      return make_error("%s: line %d: bad cluster count", name, c.line);
  }
  c.skip_space();
  if (!c.integer(&portals) || portals < 0 || portals > 8000000)
    return make_error("%s: line %d: bad portal count", name, c.line);
  out->num_leaves = int(leaves);
  out->num_clusters = int(clusters);
  out->portals.resize(size_t(portals));
  const char* what = prt2 ? "cluster" : "leaf";
  for (long i = 0; i < portals; ++i) {
    c.skip_space();
    PrtPortal& pt = out->portals[size_t(i)];
    long n = 0, a = 0, b = 0;
    if (!c.integer(&n) || n < 3 || n > 1000) return make_error("%s: line %d: portal %ld: bad point count", name, c.line, i);
    if (!c.integer(&a) || !c.integer(&b) || a < 0 || b < 0 || a >= clusters || b >= clusters || a == b)
      return make_error("%s: line %d: portal %ld: bad %s numbers", name, c.line, i, what);
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
  if (!prt2) return Status::ok();
  // Cluster membership: for every cluster in order, its leaf numbers ended by -1. Every
  // leaf belongs to exactly one cluster and every cluster has a leaf.
  out->leaf_cluster.assign(size_t(leaves), -1);
  for (long k = 0; k < clusters; ++k) {
    long members = 0;
    for (;;) {
      c.skip_space();
      long l = 0;
      if (!c.integer(&l)) return make_error("%s: line %d: cluster %ld: leaf number or -1 expected", name, c.line, k);
      if (l == -1) break;
      if (l < 0 || l >= leaves) return make_error("%s: line %d: cluster %ld: bad leaf %ld", name, c.line, k, l);
      if (out->leaf_cluster[size_t(l)] != -1)
        return make_error("%s: line %d: leaf %ld is in clusters %d and %ld", name, c.line, l,
                          out->leaf_cluster[size_t(l)], k);
      out->leaf_cluster[size_t(l)] = int(k);
      ++members;
    }
    if (members == 0) return make_error("%s: line %d: cluster %ld has no leaves", name, c.line, k);
  }
  for (long l = 0; l < leaves; ++l)
    if (out->leaf_cluster[size_t(l)] < 0) return make_error("%s: leaf %ld is in no cluster", name, l);
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

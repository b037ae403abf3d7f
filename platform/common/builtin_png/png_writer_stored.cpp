// platform/common/builtin_png/png_writer_stored.cpp: write_png_rgb without libpng.
//
// Used instead of png_writer.cpp when the build has no libpng (STARBOW_PNG=OFF, which cross
// builds choose: see cmake/StarbowCross.cmake). Same contract as platform.h states: 8-bit
// pixels + 768-byte RGB palette in, an 8-bit RGB PNG out, false with a message naming the
// file on failure. No per-call heap (one thread-local row buffer).
//
// The picture is not compressed: the zlib stream inside the single IDAT chunk holds "stored"
// deflate blocks (RFC 1951 section 3.2.4, at most 65535 bytes each), so a 320x200 shot is
// about 190 KiB. Every row uses PNG filter type 0 (none). Checksums: CRC-32 per chunk (PNG),
// Adler-32 over the raw rows (zlib, RFC 1950).
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "platform/common/platform.h"

namespace sb::platform {
namespace {

constexpr int kMaxRow = 4096;          // widest image, as png_writer.cpp
constexpr uint32_t kStoredMax = 65535;  // largest stored deflate block

struct Crc32Table {
  uint32_t v[256];
  constexpr Crc32Table() : v() {
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;  // reflected 0x04C11DB7
      v[n] = c;
    }
  }
};
constexpr Crc32Table kCrc;

// Writes bytes to the file while keeping the chunk CRC; the caller checks ferror at the end.
struct ChunkWriter {
  std::FILE* f;
  uint32_t crc = 0xFFFFFFFFu;

  void bytes(const uint8_t* p, size_t n) {
    std::fwrite(p, 1, n, f);
    for (size_t i = 0; i < n; ++i) crc = kCrc.v[(crc ^ p[i]) & 0xFFu] ^ (crc >> 8);
  }
  void be32(uint32_t x) {
    const uint8_t b[4] = {uint8_t(x >> 24), uint8_t(x >> 16), uint8_t(x >> 8), uint8_t(x)};
    bytes(b, 4);
  }
  // Length (outside the CRC), then the type, which starts the CRC.
  void begin(const char type[4], uint32_t length) {
    const uint8_t b[4] = {uint8_t(length >> 24), uint8_t(length >> 16), uint8_t(length >> 8), uint8_t(length)};
    std::fwrite(b, 1, 4, f);
    crc = 0xFFFFFFFFu;
    bytes(reinterpret_cast<const uint8_t*>(type), 4);
  }
  void end() { be32(crc ^ 0xFFFFFFFFu); }
};

// Raw image bytes -> stored deflate blocks, with the zlib Adler-32 of the raw bytes.
struct StoredDeflate {
  ChunkWriter* out;
  uint64_t raw_left;        // raw bytes still to come, over all blocks
  uint32_t block_left = 0;  // raw bytes still to come in the open block
  uint32_t a = 1, b = 0;    // Adler-32 halves

  void put(const uint8_t* p, size_t n) {
    while (n > 0) {
      if (block_left == 0) {
        const uint32_t len = raw_left < kStoredMax ? uint32_t(raw_left) : kStoredMax;
        const uint8_t header[5] = {uint8_t(len == raw_left ? 1 : 0),  // BFINAL, BTYPE 00 (stored)
                                   uint8_t(len), uint8_t(len >> 8), uint8_t(~len), uint8_t(~len >> 8)};
        out->bytes(header, 5);
        block_left = len;
      }
      const size_t take = n < block_left ? n : block_left;
      out->bytes(p, take);
      for (size_t i = 0; i < take; ++i) {
        a += p[i];
        if (a >= 65521u) a -= 65521u;
        b += a;
        if (b >= 65521u) b -= 65521u;
      }
      p += take;
      n -= take;
      block_left -= uint32_t(take);
      raw_left -= take;
    }
  }
  uint32_t adler() const { return (b << 16) | a; }
};

}  // namespace

bool write_png_rgb(const char* path, const uint8_t* pixels, int width, int height, int stride,
                   const uint8_t* palette, char* error, size_t error_size) {
  if (!pixels || !palette || width <= 0 || height <= 0 || width > kMaxRow || height > 65536 || stride < width) {
    std::snprintf(error, error_size, "%s: bad image (%dx%d, stride %d)", path, width, height, stride);
    return false;
  }
  std::FILE* f = std::fopen(path, "wb");
  if (!f) {
    std::snprintf(error, error_size, "%s: cannot open for writing", path);
    return false;
  }
  static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::fwrite(kSignature, 1, 8, f);

  ChunkWriter w{f};
  w.begin("IHDR", 13);
  w.be32(uint32_t(width));
  w.be32(uint32_t(height));
  const uint8_t ihdr_tail[5] = {8, 2, 0, 0, 0};  // depth 8, colour type 2 (RGB), deflate, filter 0, no interlace
  w.bytes(ihdr_tail, 5);
  w.end();

  const uint64_t row_bytes = 1 + uint64_t(width) * 3;  // filter byte + RGB
  const uint64_t raw = row_bytes * uint64_t(height);   // at most ~805 MB: fits one chunk
  const uint64_t blocks = (raw + kStoredMax - 1) / kStoredMax;
  w.begin("IDAT", uint32_t(2 + 5 * blocks + raw + 4));
  const uint8_t zlib_header[2] = {0x78, 0x01};  // deflate, 32 KiB window, no dictionary; 0x7801 % 31 == 0
  w.bytes(zlib_header, 2);
  StoredDeflate z{&w, raw};
  static thread_local uint8_t row[1 + kMaxRow * 3];
  for (int y = 0; y < height; ++y) {
    const uint8_t* src = pixels + size_t(y) * size_t(stride);
    row[0] = 0;  // filter: none
    for (int x = 0; x < width; ++x) std::memcpy(row + 1 + x * 3, palette + src[x] * 3, 3);
    z.put(row, size_t(row_bytes));
  }
  w.be32(z.adler());
  w.end();

  w.begin("IEND", 0);
  w.end();

  bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0) ok = false;
  if (!ok) std::snprintf(error, error_size, "%s: write failed (disk full?)", path);
  return ok;
}

}  // namespace sb::platform

#include "lvslam/io/png_check.h"

#include <cstdint>

#include <fmt/format.h>
#include <zlib.h>

#include "lvslam/core/error.h"

namespace lvslam {

namespace {

constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);

std::uint32_t bigEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return v;
}

}  // namespace

void checkPngChunks(std::string_view bytes, const std::string& path) {
  if (bytes.empty()) throw Error(path, "empty file (0 bytes)");
  if (bytes.substr(0, kSignature.size()) != kSignature) throw Error(path, "not a PNG file (no PNG signature)");
  std::size_t at = kSignature.size();
  while (at + 8 <= bytes.size()) {
    const std::size_t length = bigEndian32(bytes, at);
    const std::string type(bytes.substr(at + 4, 4));
    if (length > bytes.size() || at + 12 + length > bytes.size())
      throw Error(path, fmt::format("damaged PNG: the file ends at byte {} inside chunk '{}' of byte {} (truncated?)",
                                    bytes.size(), type, at));
    // PNG's CRC is zlib's CRC-32 (ISO 3309) over the chunk's type and data.
    const std::string_view checked = bytes.substr(at + 4, 4 + length);
    if (crc32_z(0L, reinterpret_cast<const Bytef*>(checked.data()), checked.size()) != bigEndian32(bytes, at + 8 + length))
      throw Error(path, fmt::format("damaged PNG: chunk '{}' at byte {} ({} bytes) fails its CRC", type, at, length));
    if (type == "IEND") return;
    at += 12 + length;
  }
  throw Error(path, fmt::format("damaged PNG: the file ends at byte {} without an IEND chunk (truncated?)", bytes.size()));
}

}  // namespace lvslam

#pragma once
// A PNG's chunk structure checked before it is decoded: a truncated or
// overwritten file is named with the chunk and byte offset in one error,
// rather than libpng printing its own "libpng error:" line to stderr first
// (OpenCV gives libpng no error handler of ours). A damaged stream inside a
// chunk whose CRC still matches (made on purpose) is left to the decoder.
#include <string>
#include <string_view>

namespace lvslam {

// Throws lvslam::Error(path, why) when `bytes` is not a whole PNG: no PNG
// signature, a chunk running past the end, a chunk whose CRC does not match,
// or no IEND chunk.
void checkPngChunks(std::string_view bytes, const std::string& path);

}  // namespace lvslam

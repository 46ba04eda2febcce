#pragma once
// A converted sequence folder appears whole or not at all: the converter
// writes into "<out>.partial", marked incomplete, and renames it to <out>
// only once everything is written. A conversion that fails leaves nothing;
// one that is killed leaves the marked ".partial" folder, which readers
// refuse (SequenceReader) instead of reading a silently short recording.
#include <functional>
#include <string>

namespace lvslam {

// The marker file of a folder whose writing has not finished.
inline constexpr const char* kIncompleteMarker = "INCOMPLETE";

// Runs `write(partial_dir)` and renames partial_dir to `out_dir` when it
// returns. An existing `out_dir` is replaced only when it is an earlier
// sequence folder (it has sequence.yaml) or empty; otherwise, or when
// `write` throws, nothing is left and the error goes on.
void writeFolderAtomically(const std::string& out_dir, const std::function<void(const std::string&)>& write);

}  // namespace lvslam

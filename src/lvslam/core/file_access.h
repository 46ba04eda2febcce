#pragma once
// Filesystem queries that fail as lvslam::Error naming the file (and the line
// that named it) rather than as std::filesystem_error: a name too long, a
// folder without permission, a symlink loop are bad input (exit 2).
#include <fstream>
#include <string>

namespace lvslam {

enum class FileKind { kMissing, kRegular, kDirectory, kOther };

// What `path` is. Throws Error(where, "cannot access '<path>': <reason>")
// when the system cannot tell; `where` defaults to the path itself.
FileKind fileKind(const std::string& path, const std::string& where = "");

// A stream on the regular file `path`. Throws Error(where, why) when it is
// missing, a folder, or cannot be read (with the system's reason).
std::ifstream openInputFile(const std::string& path, const std::string& where = "",
                            std::ios::openmode mode = std::ios::in);

}  // namespace lvslam

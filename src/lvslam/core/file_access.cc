#include "lvslam/core/file_access.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "lvslam/core/error.h"

namespace lvslam {

namespace fs = std::filesystem;

FileKind fileKind(const std::string& path, const std::string& where) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  // Not found and a parent that is a file are plain "missing"; anything else
  // the system could not answer (EACCES, ELOOP, ENAMETOOLONG) is named as is.
  if (status.type() == fs::file_type::not_found || ec == std::errc::not_a_directory) return FileKind::kMissing;
  if (ec) throw Error(where.empty() ? path : where, "cannot access '" + path + "': " + ec.message());
  if (status.type() == fs::file_type::regular) return FileKind::kRegular;
  if (status.type() == fs::file_type::directory) return FileKind::kDirectory;
  return FileKind::kOther;
}

std::ifstream openInputFile(const std::string& path, const std::string& where, std::ios::openmode mode) {
  const std::string at = where.empty() ? path : where;
  const FileKind kind = fileKind(path, at);
  const std::string named = where.empty() ? "" : "'" + path + "' ";
  if (kind == FileKind::kMissing) throw Error(at, named + "file not found");
  if (kind == FileKind::kDirectory) throw Error(at, named + "is a folder, not a file");
  errno = 0;
  std::ifstream in(path, mode);
  if (!in) throw Error(at, named + "cannot read: " + (errno ? std::strerror(errno) : "open failed"));
  return in;
}

}  // namespace lvslam

#include "lvslam/io/atomic_folder.h"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"

namespace lvslam {

namespace {

namespace fs = std::filesystem;

// Checked before anything is converted, so a refusal costs no time.
void checkReplaceable(const std::string& out_dir) {
  const FileKind kind = fileKind(out_dir);
  if (kind == FileKind::kMissing) return;
  std::error_code ec;
  if (kind == FileKind::kDirectory && (fs::is_empty(out_dir, ec) || fs::exists(fs::path(out_dir) / "sequence.yaml")))
    return;
  throw Error(out_dir, "exists and is not a sequence folder: not replaced");
}

}  // namespace

void writeFolderAtomically(const std::string& out_dir, const std::function<void(const std::string&)>& write) {
  checkReplaceable(out_dir);
  const fs::path partial = fs::path(out_dir).lexically_normal().string() + ".partial";
  std::error_code ec;
  fs::remove_all(partial, ec);
  fs::create_directories(partial, ec);
  if (ec) throw Error(partial.string(), "cannot create the folder: " + ec.message());
  std::ofstream(partial / kIncompleteMarker) << "written by lvslam; the conversion has not finished\n";
  try {
    write(partial.string());
  } catch (...) {
    fs::remove_all(partial, ec);
    throw;
  }
  fs::remove(partial / kIncompleteMarker, ec);
  fs::remove_all(out_dir, ec);
  fs::rename(partial, out_dir, ec);
  if (ec) throw Error(out_dir, "cannot move the converted folder " + partial.string() + " here: " + ec.message());
}

}  // namespace lvslam

#include "lvslam/system/output_folder.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <regex>
#include <system_error>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"

namespace lvslam::system {

namespace {

namespace fs = std::filesystem;

void removeFile(const fs::path& path) {
  std::error_code ec;
  fs::remove(path, ec);
  if (ec) throw Error(path.string(), "cannot remove an earlier run's output: " + ec.message());
}

}  // namespace

void prepareOutputFolder(const std::string& out_dir) {
  const fs::path dir(out_dir);
  const FileKind kind = fileKind(out_dir);
  if (kind != FileKind::kMissing && kind != FileKind::kDirectory) throw Error(out_dir, "the output folder is not a folder");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(out_dir, "cannot create the output folder: " + ec.message());
  if (::access(out_dir.c_str(), W_OK) != 0)
    throw Error(out_dir, std::string("cannot write in the output folder: ") + std::strerror(errno));
  for (const char* name :
       {"trajectory.tum", "trajectory_refined.tum", "trajectory_in_map.tum", "stats.json", "stats_frames.jsonl",
        "map.ply", "lines.ply"})
    removeFile(dir / name);
  const fs::path own = dir / "subsystems";
  if (!fs::is_directory(own, ec)) return;
  const std::regex ours(R"(visual_map_\d+\.tum|lidar_camera\.tum)");
  for (const fs::directory_entry& entry : fs::directory_iterator(own, ec))
    if (std::regex_match(entry.path().filename().string(), ours)) removeFile(entry.path());
  if (ec) throw Error(own.string(), "cannot list an earlier run's outputs: " + ec.message());
  fs::remove(own, ec);  // only when nothing else is left in it
}

}  // namespace lvslam::system

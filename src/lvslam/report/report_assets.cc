#include "lvslam/report/report_assets.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace lvslam::report {

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> candidateFolders() {
  if (const char* env = std::getenv("LVSLAM_REPORT_ASSETS"); env && *env) return {fs::path(env)};
  std::vector<fs::path> folders;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) folders.push_back(exe.parent_path().parent_path() / "share" / "lvslam" / "report");
  folders.push_back(fs::path(LVSLAM_REPORT_ASSET_DIR));
  return folders;
}

std::optional<std::string> slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::optional<ReportAssets> loadFrom(const fs::path& dir) {
  ReportAssets assets;
  assets.dir = dir.string();
  const std::pair<const char*, std::string*> files[] = {
      {"three.module.min.js", &assets.three_js}, {"OrbitControls.js", &assets.orbit_controls_js},
      {"chart.umd.min.js", &assets.chart_js},    {"report.js", &assets.report_js},
      {"report.css", &assets.report_css}};
  for (const auto& [name, text] : files) {
    std::optional<std::string> content = slurp(dir / name);
    if (!content || content->empty()) return std::nullopt;
    *text = std::move(*content);
  }
  return assets;
}

}  // namespace

std::optional<ReportAssets> loadReportAssets(std::string* looked_in) {
  std::string tried;
  for (const fs::path& dir : candidateFolders()) {
    if (std::optional<ReportAssets> assets = loadFrom(dir)) return assets;
    tried += (tried.empty() ? "" : ", ") + dir.string();
  }
  if (looked_in) *looked_in = tried;
  return std::nullopt;
}

std::string missingAssetsReason(const std::string& looked_in) {
  return "the report's JavaScript assets are missing (looked in " + looked_in +
         "); install them with scripts/install-deps.sh (npm ci in web/), then build again";
}

std::string missingAssetsWarning(const std::string& file, const std::string& looked_in) {
  return "warning: " + file + " not written: " + missingAssetsReason(looked_in) + "\n";
}

}  // namespace lvslam::report

#include "lvslam/report/html_page.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "lvslam/core/error.h"

namespace lvslam::report {

namespace {

// "</script" would end the inline element early and "<!--" would switch the
// HTML parser into its escaped script state; "<\/script" and "<\!--" are the
// same text inside a JavaScript string, regular expression or comment, the
// only places either can occur in valid code.
std::string inlineSafe(const std::string& code) {
  std::string out;
  out.reserve(code.size() + 64);
  for (std::size_t i = 0; i < code.size(); ++i) {
    out += code[i];
    if (code[i] != '<') continue;
    std::string next = code.substr(i + 1, 7);
    for (char& c : next) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (next == "/script" || next.rfind("!--", 0) == 0) out += '\\';
  }
  return out;
}

std::string htmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

// JSON text made safe inside <script>: '<' (only ever inside a JSON string)
// becomes \u003c, which every JSON reader reads back as the same string.
void writeScriptSafe(std::ostream& out, std::string_view json) {
  for (std::size_t at = json.find('<'); at != std::string_view::npos; at = json.find('<')) {
    out << json.substr(0, at) << "\\u003c";
    json.remove_prefix(at + 1);
  }
  out << json;
}

}  // namespace

void writeHtmlPage(std::ostream& out, const std::string& title, const eval::JsonObject& data,
                   const ReportAssets& assets, bool with_3d) {
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << htmlEscape(title)
      << "</title>\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<style>\n"
      << assets.report_css << "\n</style>\n</head>\n<body>\n<div id=\"app\"></div>\n";
  out << "<script type=\"application/json\" id=\"lvslam-data\">";
  data.write([&out](std::string_view piece) { writeScriptSafe(out, piece); });
  out << "</script>\n";
  // The ES modules of three.js load from blob URLs made of these texts.
  if (with_3d)
    out << "<script type=\"text/plain\" id=\"three-module\">" << inlineSafe(assets.three_js) << "</script>\n";
  if (with_3d)
    out << "<script type=\"text/plain\" id=\"orbit-controls-module\">" << inlineSafe(assets.orbit_controls_js)
        << "</script>\n";
  out << "<script>\n" << inlineSafe(assets.chart_js) << "\n</script>\n";
  out << "<script>\n" << inlineSafe(assets.report_js) << "\n</script>\n</body>\n</html>\n";
}

std::string htmlPage(const std::string& title, const eval::JsonObject& data, const ReportAssets& assets,
                     bool with_3d) {
  std::ostringstream out;
  writeHtmlPage(out, title, data, assets, with_3d);
  return out.str();
}

void writeHtmlFile(const std::string& path, const std::string& title, const eval::JsonObject& data,
                   const ReportAssets& assets, bool with_3d) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    writeHtmlPage(out, title, data, assets, with_3d);
    if (!out) throw Error(path, "cannot write the file");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) throw Error(path, "cannot write the file: " + ec.message());
}

}  // namespace lvslam::report

#include "lvslam/report/html_page.h"

#include <cctype>
#include <filesystem>
#include <fstream>

#include "lvslam/core/error.h"
#include "lvslam/report/report_json.h"

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

}  // namespace

std::string htmlPage(const std::string& title, const std::string& data_json, const ReportAssets& assets,
                     bool with_3d) {
  std::string html;
  html.reserve(data_json.size() + assets.three_js.size() + assets.chart_js.size() + 200000);
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + htmlEscape(title) +
          "</title>\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<style>\n" +
          assets.report_css + "\n</style>\n</head>\n<body>\n<div id=\"app\"></div>\n";
  html += "<script type=\"application/json\" id=\"lvslam-data\">" + scriptSafe(data_json) + "</script>\n";
  // The ES modules of three.js load from blob URLs made of these texts.
  if (with_3d)
    html += "<script type=\"text/plain\" id=\"three-module\">" + inlineSafe(assets.three_js) + "</script>\n";
  if (with_3d)
    html += "<script type=\"text/plain\" id=\"orbit-controls-module\">" + inlineSafe(assets.orbit_controls_js) +
            "</script>\n";
  html += "<script>\n" + inlineSafe(assets.chart_js) + "\n</script>\n";
  html += "<script>\n" + inlineSafe(assets.report_js) + "\n</script>\n</body>\n</html>\n";
  return html;
}

void writeHtmlFile(const std::string& path, const std::string& html) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << html;
    if (!out) throw Error(path, "cannot write the file");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) throw Error(path, "cannot write the file: " + ec.message());
}

}  // namespace lvslam::report

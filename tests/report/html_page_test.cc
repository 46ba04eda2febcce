#include "lvslam/report/html_page.h"

#include <gtest/gtest.h>

namespace lvslam::report {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

ReportAssets assets() {
  ReportAssets a;
  a.three_js = "export const s = '</script><script>alert(1)</script>';";
  a.orbit_controls_js = "import {A} from 'three'; const c = '<!-- x';";
  a.chart_js = "var Chart = 1; // </SCRIPT>";
  a.report_js = "console.log('report');";
  a.report_css = "body {}";
  return a;
}

TEST(HtmlPage, NoInlinedTextEndsItsScriptEarly) {
  eval::JsonObject data;
  data.addString("kind", "run").addString("reason", "</script><!--");
  const std::string html = htmlPage("t <b>", data, assets());
  // Only the five script elements the page has end one: data, two module
  // texts, Chart.js, report.js ("<script" inside a script's text is inert).
  EXPECT_EQ(count(html, "</script>"), 5u);
  EXPECT_EQ(count(html, "</SCRIPT>"), 0u);
  EXPECT_EQ(count(html, "<!--"), 0u);
  EXPECT_NE(html.find(R"("reason": "\u003c/script>\u003c!--")"), std::string::npos);
  EXPECT_NE(html.find("'<\\/script><script>alert(1)<\\/script>'"), std::string::npos);
  EXPECT_NE(html.find("<title>t &lt;b&gt;</title>"), std::string::npos);
}

TEST(HtmlPage, WithoutThe3dViewThreeIsLeftOut) {
  const std::string html = htmlPage("bench", eval::JsonObject().addString("kind", "bench"), assets(), false);
  EXPECT_EQ(html.find("three-module"), std::string::npos);
  EXPECT_EQ(count(html, "</script>"), 3u);
}

}  // namespace
}  // namespace lvslam::report

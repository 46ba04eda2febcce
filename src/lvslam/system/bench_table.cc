#include "lvslam/system/bench_table.h"

#include <algorithm>

#include <fmt/format.h>

namespace lvslam::system {

namespace {

std::optional<BenchCell> cellOf(const BenchRow& row, const std::string& column) {
  const auto it = row.cells.find(column);
  if (it == row.cells.end()) return std::nullopt;
  return it->second;
}

std::string header(const std::vector<std::string>& columns) {
  std::string text = "| sequence |", rule = "|---|";
  for (const std::string& c : columns) {
    text += " " + c + " |";
    rule += "---:|";
  }
  return text + "\n" + rule + "\n";
}

template <typename CellText>
std::string table(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns, CellText cell_text) {
  std::string text = header(columns);
  for (const BenchRow& row : rows) {
    text += "| " + row.sequence + " |";
    for (const std::string& c : columns) text += " " + cell_text(cellOf(row, c)) + " |";
    text += "\n";
  }
  return text;
}

}  // namespace

std::string accuracyCellText(const std::optional<BenchCell>& cell) {
  if (!cell) return "";
  if (!cell->failure.empty()) return "fail";
  if (cell->lost_fraction > 0.5) return "x";  // the paper's mark for a run that lost track
  if (!cell->ate_mean_m) return "n/a";
  return fmt::format("{:.4f}", *cell->ate_mean_m);
}

BenchRow meanRow(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns, const std::string& label) {
  BenchRow mean{label, {}};
  for (const std::string& column : columns) {
    const bool everywhere = !rows.empty() && std::all_of(rows.begin(), rows.end(), [&](const BenchRow& row) {
      return cellOf(row, column).has_value();
    });
    if (!everywhere) continue;
    BenchCell out;
    double ate_sum = 0.0, rtf_sum = 0.0;
    std::size_t with_ate = 0;
    for (const BenchRow& row : rows) {
      const BenchCell cell = *cellOf(row, column);
      if (!cell.failure.empty()) out.failure = cell.failure;
      out.lost_fraction = std::max(out.lost_fraction, cell.lost_fraction);
      out.peak_rss_mib = std::max(out.peak_rss_mib, cell.peak_rss_mib);
      rtf_sum += cell.real_time_factor;
      if (cell.ate_mean_m) {
        ate_sum += *cell.ate_mean_m;
        ++with_ate;
      }
    }
    out.real_time_factor = rtf_sum / static_cast<double>(rows.size());
    if (with_ate == rows.size()) out.ate_mean_m = ate_sum / static_cast<double>(with_ate);
    mean.cells[column] = out;
  }
  return mean;
}

std::string accuracyTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns) {
  return table(rows, columns, accuracyCellText);
}

std::string speedTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns) {
  return table(rows, columns, [](const std::optional<BenchCell>& cell) -> std::string {
    if (!cell || !cell->failure.empty()) return cell ? "fail" : "";
    return fmt::format("{:.2f}x, {:.0f} MiB", cell->real_time_factor, cell->peak_rss_mib);
  });
}

std::string replaceMarkedSection(const std::string& document, const std::string& section) {
  const std::string begin = kBenchBeginMarker, end = kBenchEndMarker;
  const std::string block = begin + "\n" + section + (section.empty() || section.back() == '\n' ? "" : "\n") + end;
  const auto b = document.find(begin);
  const auto e = b == std::string::npos ? std::string::npos : document.find(end, b);
  if (b == std::string::npos || e == std::string::npos) {
    const std::string separator = document.empty() || document.back() == '\n' ? "\n" : "\n\n";
    return document + separator + block + "\n";
  }
  return document.substr(0, b) + block + document.substr(e + end.size());
}

}  // namespace lvslam::system

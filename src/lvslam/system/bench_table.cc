#include "lvslam/system/bench_table.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace lvslam::system {

namespace {

std::optional<BenchCell> cellOf(const BenchRow& row, const std::string& column) {
  const auto it = row.cells.find(column);
  if (it == row.cells.end()) return std::nullopt;
  return it->second;
}

std::string header(const std::string& first, const std::vector<std::string>& columns) {
  std::string text = "| " + first + " |", rule = "|---|";
  for (const std::string& c : columns) {
    text += " " + c + " |";
    rule += "---:|";
  }
  return text + "\n" + rule + "\n";
}

template <typename CellText>
std::string table(const std::string& first, const std::vector<BenchRow>& rows, const std::vector<std::string>& columns,
                  CellText cell_text) {
  std::string text = header(first, columns);
  for (const BenchRow& row : rows) {
    text += "| " + row.sequence + " |";
    for (const std::string& c : columns) {
      // Appended piece by piece: `" " + cell + " |"` trips GCC 12's false -Wrestrict.
      text += ' ';
      text += cell_text(cellOf(row, c));
      text += " |";
    }
    text += "\n";
  }
  return text;
}

// The marks that replace a cell's figures: "" (not run), "fail", and, when
// `lost_counts`, "x" (lost more than half: its accuracy means nothing).
std::optional<std::string> mark(const std::optional<BenchCell>& cell, bool lost_counts) {
  if (!cell) return "";
  if (!cell->failure.empty()) return "fail";
  if (lost_counts && cell->lost_fraction > 0.5) return "x";  // the paper's mark for a run that lost track
  return std::nullopt;
}

std::string metres(const std::optional<double>& value) {
  return value ? fmt::format("{:.4f}", *value) : "n/a";
}

// One accuracy figure of a cell, or the mark that replaces it.
std::string markedMetres(const std::optional<BenchCell>& cell, std::optional<double> BenchCell::*figure) {
  if (const auto m = mark(cell, true)) return *m;
  return metres((*cell).*figure);
}

// The mean of one figure over all rows' cells, none unless every row has it.
std::optional<double> meanOf(const std::vector<BenchRow>& rows, const std::string& column,
                             std::optional<double> BenchCell::*figure) {
  double sum = 0.0;
  for (const BenchRow& row : rows) {
    const std::optional<double> value = (*cellOf(row, column)).*figure;
    if (!value) return std::nullopt;
    sum += *value;
  }
  return sum / static_cast<double>(rows.size());
}

// "3.00x / 2.50x, 140 MiB" (online pipeline / whole run), with `latency`
// "3.00x / 2.50x, 133 ms, 140 MiB" (a lost run still has its speed: no x).
std::string speedCellText(const std::optional<BenchCell>& cell, bool latency) {
  if (const auto m = mark(cell, false)) return *m;
  std::string median;
  if (latency) median = cell->latency_median_ms ? fmt::format("{:.0f} ms, ", *cell->latency_median_ms) : "n/a, ";
  return fmt::format("{:.2f}x / {:.2f}x, {}{:.0f} MiB", cell->online_real_time_factor, cell->real_time_factor, median,
                     cell->peak_rss_mib);
}

// The online ATE of a column that counts in the verdict.
std::optional<double> contender(const BenchRow& row, const std::string& column) {
  const std::optional<BenchCell> cell = cellOf(row, column);
  if (mark(cell, true)) return std::nullopt;
  return cell->ate_rmse_m;
}

std::string verdictText(const FamilySummary& family) {
  std::string text = fusionVerdict(family.row).text;
  if (family.seed_rows.size() < 2) return text;
  const auto wins = std::count_if(family.seed_rows.begin(), family.seed_rows.end(),
                                  [](const BenchRow& seed) { return fusionVerdict(seed).fused_beats; });
  return text + fmt::format("; {} of {} seeds", wins, family.seed_rows.size());
}

}  // namespace

std::string accuracyCellText(const std::optional<BenchCell>& cell) {
  return markedMetres(cell, &BenchCell::ate_mean_m);
}

BenchRow meanRow(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns, const std::string& label) {
  BenchRow mean{label, {}};
  for (const std::string& column : columns) {
    const bool everywhere = !rows.empty() && std::all_of(rows.begin(), rows.end(), [&](const BenchRow& row) {
      return cellOf(row, column).has_value();
    });
    if (!everywhere) continue;
    BenchCell out;
    double rtf_sum = 0.0, online_rtf_sum = 0.0;
    for (const BenchRow& row : rows) {
      const BenchCell cell = *cellOf(row, column);
      if (!cell.failure.empty()) out.failure = cell.failure;
      out.lost_fraction = std::max(out.lost_fraction, cell.lost_fraction);
      out.peak_rss_mib = std::max(out.peak_rss_mib, cell.peak_rss_mib);
      rtf_sum += cell.real_time_factor;
      online_rtf_sum += cell.online_real_time_factor;
    }
    out.real_time_factor = rtf_sum / static_cast<double>(rows.size());
    out.online_real_time_factor = online_rtf_sum / static_cast<double>(rows.size());
    for (auto figure : {&BenchCell::ate_mean_m, &BenchCell::ate_rmse_m, &BenchCell::refined_ate_rmse_m,
                        &BenchCell::vision_share, &BenchCell::latency_median_ms})
      out.*figure = meanOf(rows, column, figure);
    mean.cells[column] = out;
  }
  return mean;
}

std::string accuracyTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns) {
  return table("sequence", rows, columns, accuracyCellText);
}

std::string speedTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns) {
  return table("sequence", rows, columns, [](const auto& cell) { return speedCellText(cell, false); });
}

std::string familyAccuracyCellText(const std::optional<BenchCell>& cell) {
  if (const auto m = mark(cell, true)) return *m;
  std::string text = metres(cell->ate_rmse_m) + " / " + metres(cell->refined_ate_rmse_m);
  if (cell->vision_share) text += fmt::format(", {:.0f} %", 100.0 * *cell->vision_share);
  return text;
}

std::string familyAccuracyTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns) {
  return table("seed", rows, columns, familyAccuracyCellText);
}

std::string familySpeedTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns) {
  return table("seed", rows, columns, [](const auto& cell) { return speedCellText(cell, true); });
}

FusionVerdict fusionVerdict(const BenchRow& row) {
  FusionVerdict verdict;
  const std::optional<double> fused = contender(row, "fused");
  if (!fused) {
    const std::string why = mark(cellOf(row, "fused"), true).value_or("n/a");
    verdict.text = "no (fused " + (why.empty() ? std::string("not run") : why) + ")";
    return verdict;
  }
  const std::optional<double> lidar = contender(row, "lidar"), visual = contender(row, "visual");
  if (!lidar && !visual) {
    verdict.fused_beats = true;
    verdict.text = "yes (neither single mode tracks)";
    return verdict;
  }
  const bool lidar_better = lidar && (!visual || *lidar <= *visual);
  verdict.better_single = lidar_better ? "lidar" : "visual";
  const double single = lidar_better ? *lidar : *visual;
  verdict.fused_beats = *fused < single;
  verdict.gain_percent = 100.0 * (single - *fused) / single;
  verdict.text = fmt::format("{}, {:.1f} % {} {}", verdict.fused_beats ? "yes" : "no", std::abs(*verdict.gain_percent),
                             verdict.fused_beats ? "below" : "above", verdict.better_single);
  return verdict;
}

std::string familySummaryTable(const std::vector<FamilySummary>& families) {
  std::string text =
      "| family | weaker sensor | lidar | visual | fused | fused, refined | fused beats the better single mode |\n"
      "|---|---|---:|---:|---:|---:|---|\n";
  constexpr auto online = &BenchCell::ate_rmse_m;
  for (const FamilySummary& f : families) {
    const std::optional<BenchCell> fused = cellOf(f.row, "fused");
    text += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", f.family, f.weaker_sensor,
                        markedMetres(cellOf(f.row, "lidar"), online), markedMetres(cellOf(f.row, "visual"), online),
                        markedMetres(fused, online), markedMetres(fused, &BenchCell::refined_ate_rmse_m),
                        verdictText(f));
  }
  return text;
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

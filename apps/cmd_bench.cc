// `lvslam bench`: a simulated suite in the modes lidar, visual and fused plus
// the ablations of the paper's contributions; prints the tables and writes
// them into docs/benchmarks.md. Two suites: `classic` (room, hall, gate, gate
// at night, room with a camera blackout, and any sequence folders given;
// the paper-style tables) and `families` (sim/families.h: scenes where one
// sensor is the weaker one, seeds 1..N, a table per family and a summary that
// says whether fused beats the better single mode). Each run is its own
// `lvslam run` process, so its peak memory is its own.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "command.h"
#include "lvslam/core/error.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/sim/families.h"
#include "lvslam/sim/simulate_sequence.h"
#include "lvslam/report/bench_report_page.h"
#include "lvslam/system/bench_json.h"
#include "lvslam/system/bench_table.h"

namespace lvslam::apps {

namespace fs = std::filesystem;

namespace {

struct BenchArgs {
  std::string suite = "classic";
  std::vector<std::string> sequences;
  std::vector<std::string> families;  // families suite: these only (default all)
  bool quick = false;                 // families suite: one seed, 15 s unless --duration
  double duration = 60.0;
  bool duration_given = false;
  std::string work_dir = "out/bench";
  std::string config_path = "config/sim.yaml";
  std::string doc_path = "docs/benchmarks.md";
  bool no_doc = false;
  bool no_ablations = false;
  int seeds = 1;  // classic: room, hall and gate with seeds 1..seeds; families: every family
};

struct Column {
  std::string name;    // table heading
  std::string folder;  // its runs' folder under runs/<sequence>/
  std::vector<std::string> run_args;
};

Column ablationColumn(const std::string& name, const std::string& ablation) {
  return {name, "fused-ablate-" + ablation, {"--mode", "fused", "--ablate", ablation}};
}

std::vector<Column> columns(bool ablations) {
  std::vector<Column> out = {{"lidar", "lidar", {"--mode", "lidar"}},
                             {"visual", "visual", {"--mode", "visual"}},
                             {"fused", "fused", {"--mode", "fused"}}};
  if (!ablations) return out;
  out.push_back(ablationColumn("fused w/o e_dir", "direction-residual"));
  out.push_back(ablationColumn("fused w/o d_v_mean", "lidar-direction-refinement"));
  out.push_back(ablationColumn("fused w/o fusion lines", "fusion-lines"));
  // lvslam's additions to the paper (docs/visual-subsystem.md, docs/architecture.md).
  out.push_back(ablationColumn("fused w/o keypoint depths", "keypoint-depths"));
  out.push_back(ablationColumn("fused, paper's output", "paper-output"));
  return out;
}

struct SuiteSequence {
  std::string name;
  sim::SimOptions options;
};

// Room, hall and gate with one seed (other furniture, other noise); rows
// "room" for seed 1, "room-seed2" for the others.
std::vector<SuiteSequence> daylightSuite(double duration, int seed) {
  std::vector<SuiteSequence> suite;
  for (const char* scenario : {"room", "hall", "gate"}) {
    sim::SimOptions o;
    o.scenario = scenario;
    o.duration = duration;
    o.seed = static_cast<std::uint64_t>(seed);
    suite.push_back({seed == 1 ? std::string(scenario) : fmt::format("{}-seed{}", scenario, seed), o});
  }
  return suite;
}

// The suite's seed-1 sequences, then (seeds > 1) the daylight ones again with
// seeds 2..seeds: a fused run scatters by centimetres under changes that
// leave the mathematics alone (docs/history/2026-11-fusion-sessions.md, "Fused
// mode over nine sequences"), so one seed is one draw.
std::vector<SuiteSequence> simulatedSuite(double duration, int seeds) {
  std::vector<SuiteSequence> suite = daylightSuite(duration, 1);
  suite.push_back({"gate-night", suite[2].options});
  suite.back().options.night = true;
  suite.push_back({"room-blackout", suite[0].options});
  // Dark for a sixth of the run, from 40 % on: vision fails and must recover.
  suite.back().options.camera_blackout = sim::TimeInterval{0.4 * duration, 0.4 * duration + duration / 6.0};
  for (int seed = 2; seed <= seeds; ++seed) {
    const std::vector<SuiteSequence> more = daylightSuite(duration, seed);
    suite.insert(suite.end(), more.begin(), more.end());
  }
  return suite;
}

// Simulated once per duration.
std::string ensureSimulated(const SuiteSequence& s, const fs::path& cache) {
  const fs::path dir = cache / fmt::format("{}-{:g}s", s.name, s.options.duration);
  sim::simulateSequenceOnce(s.options, dir.string(), [&] {
    std::cout << "simulating " << s.name << " (" << s.options.duration << " s) into " << dir.string() << "\n"
              << std::flush;
  });
  return dir.string();
}

// Runs this binary with `args`, output to `log`; returns the exit code.
int runSelf(const std::vector<std::string>& args, const fs::path& log) {
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::vector<std::string> all = {self};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw Error("lvslam bench", "cannot start " + self);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string lastLine(const fs::path& path) {
  std::ifstream file(path);
  std::string line, last;
  while (std::getline(file, line))
    if (!line.empty()) last = line;
  return last;
}

// The number at `path` below `node`; none when a key is absent or null
// (stats.json writes null for a figure it has no data for). Recursive, not a
// loop reassigning one node: assigning a yaml-cpp node overwrites the node it
// shares with the document.
std::optional<double> findNumber(const YamlConfig& node, const std::vector<std::string>& path, std::size_t depth = 0) {
  const std::optional<YamlConfig> child = node.find(path[depth]);
  if (!child) return std::nullopt;
  return depth + 1 == path.size() ? std::optional(child->asDouble()) : findNumber(*child, path, depth + 1);
}

system::BenchCell runCell(const std::string& sequence, const Column& column, const std::string& config,
                          const fs::path& out) {
  fs::create_directories(out);
  std::vector<std::string> args = {"run", "--sequence", sequence, "--out", out.string()};
  if (!config.empty()) args.insert(args.end(), {"--config", config});
  args.insert(args.end(), column.run_args.begin(), column.run_args.end());
  system::BenchCell cell;
  if (runSelf(args, out / "log.txt") != 0) {
    cell.failure = lastLine(out / "log.txt");
    return cell;
  }
  const YamlConfig summary = YamlConfig::loadFile((out / "stats.json").string()).at("summary");
  cell.lost_fraction = summary.at("lost_fraction").asDouble();
  cell.real_time_factor = summary.at("real_time_factor").asDouble();
  cell.online_real_time_factor = summary.at("online_real_time_factor").asDouble();
  cell.peak_rss_mib = summary.at("peak_rss_mib").asDouble();
  cell.ate_mean_m = findNumber(summary, {"accuracy", "aligned_mean_translation_error"});
  cell.ate_rmse_m = findNumber(summary, {"accuracy", "ate", "rmse"});
  cell.refined_ate_rmse_m = findNumber(summary, {"accuracy_refined", "ate", "rmse"});
  cell.latency_median_ms = findNumber(summary, {"latency_ms", "median"});
  const double images = summary.at("images").asDouble();
  if (summary.at("mode").asString() != "lidar" && images > 0)
    cell.vision_share = summary.at("visual_output_frames").asDouble() / images;
  return cell;
}

std::string machine() {
  std::string os = "Linux", cpu = "unknown CPU";
  std::ifstream release("/etc/os-release"), cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(release, line);)
    if (line.rfind("PRETTY_NAME=", 0) == 0) {
      os = line.substr(12);
      std::erase(os, '"');
    }
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  return fmt::format("{}, {} cores ({})", os, std::thread::hardware_concurrency(), cpu);
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", std::localtime(&now));
  return text;
}

std::string report(const std::vector<system::BenchRow>& rows, const std::vector<std::string>& names,
                   const std::string& command, double duration) {
  return fmt::format(
      "### Accuracy and speed table (`lvslam bench`)\n\n"
      "Command: `{}` on {}, {}. Simulated sequences of {:g} s (docs/simulator.md).\n\n"
      "Aligned mean translation error (ATE mean, m; SE3 alignment when metric, Sim3 otherwise), as in the paper's "
      "Tables I and II; x: the run lost track for more than half of its frames.\n\n{}\n"
      "Real-time factor (sequence seconds per wall second, reading included) of the online pipeline / of the whole "
      "run (the offline refinement included) and peak memory of each run:\n\n{}",
      command, machine(), today(), duration, system::accuracyTable(rows, names), system::speedTable(rows, names));
}

std::vector<std::string> columnNames(const std::vector<Column>& cols) {
  std::vector<std::string> names;
  for (const Column& c : cols) names.push_back(c.name);
  return names;
}

using CellText = std::string (*)(const std::optional<system::BenchCell>&);

// Every column on one sequence, each run's output under runs_dir/<column
// folder>; `progress` shows each result as it comes.
system::BenchRow runRow(const std::string& label, const std::string& dir, const std::vector<Column>& cols,
                        const std::string& config, const fs::path& runs_dir, CellText progress) {
  system::BenchRow row{label, {}};
  for (const Column& c : cols) {
    std::cout << fmt::format("{:<16} {:<27}", label, c.name) << std::flush;
    // Sequences without the sensors of a mode are skipped by `run` with an error: shown as fail.
    row.cells[c.name] = runCell(dir, c, config, runs_dir / c.folder);
    std::cout << progress(row.cells[c.name]) << "\n";
  }
  return row;
}

// Prints the tables and, unless --no-doc, writes them into the document's
// marked section (the previous suite's tables are replaced).
int publish(const BenchArgs& args, const std::string& text) {
  std::cout << "\n" << text;
  if (args.no_doc) return 0;
  std::stringstream document;
  if (std::ifstream in{args.doc_path}) document << in.rdbuf();
  std::ofstream out(args.doc_path);
  out << system::replaceMarkedSection(document.str(), text);
  if (!out) throw Error(args.doc_path, "cannot write the file");
  std::cout << "wrote the tables into " << args.doc_path << "\n";
  return 0;
}

// bench.html beside the markdown (in the work folder with --no-doc): the
// tables with bars per mode.
void writeBenchPage(const BenchArgs& args, const std::string& command, const std::vector<std::string>& groups) {
  const fs::path path = (args.no_doc ? fs::path(args.work_dir) : fs::path(args.doc_path).parent_path()) / "bench.html";
  std::string looked_in;
  if (const std::optional<report::ReportAssets> assets = report::loadReportAssets(&looked_in)) {
    report::writeBenchReport(path.string(), command, groups, *assets);
    std::cout << "wrote " << path.string() << "\n";
  } else {
    std::cout << report::missingAssetsWarning(path.string(), looked_in);
  }
}

int runClassic(const BenchArgs& args, const std::string& command) {
  if (!args.families.empty()) throw Error("--families", "only with --suite families");
  if (args.quick) throw Error("--quick", "only with --suite families");
  const fs::path work(args.work_dir);
  const std::vector<Column> cols = columns(!args.no_ablations);
  const std::vector<std::string> names = columnNames(cols);
  const std::string config = fs::exists(args.config_path) ? args.config_path : "";
  std::vector<std::pair<std::string, std::string>> sequences;  // row name, folder
  std::set<std::string> daylight_names;  // the rows the mean over seeds covers
  for (const SuiteSequence& s : simulatedSuite(args.duration, args.seeds)) {
    sequences.push_back({s.name, ensureSimulated(s, work / "sequences")});
    if (!s.options.night && !s.options.camera_blackout) daylight_names.insert(s.name);
  }
  for (const std::string& dir : args.sequences) {
    if (!fs::exists(fs::path(dir) / "sequence.yaml")) throw Error(dir, "not a sequence folder (no sequence.yaml)");
    sequences.push_back({fs::path(dir).filename().string(), dir});
  }
  std::vector<system::BenchRow> rows;
  for (const auto& [name, dir] : sequences)
    rows.push_back(runRow(name, dir, cols, config, work / "runs" / name, system::accuracyCellText));
  if (args.seeds > 1) {
    std::vector<system::BenchRow> daylight;
    for (const system::BenchRow& row : rows)
      if (daylight_names.count(row.sequence)) daylight.push_back(row);
    rows.push_back(system::meanRow(daylight, names, fmt::format("mean, room/hall/gate x seeds 1-{}", args.seeds)));
  }
  const int code = publish(args, report(rows, names, command, args.duration));
  writeBenchPage(args, command, {system::benchGroupJson("classic suite", "", rows, names)});
  return code;
}

std::string weakerSensorText(sim::WeakerSensor weaker) {
  switch (weaker) {
    case sim::WeakerSensor::kLidar: return "LiDAR";
    case sim::WeakerSensor::kCamera: return "camera";
    case sim::WeakerSensor::kNeither: break;
  }
  return "neither";
}

// The purpose line (lower case in sim::families()) as a sentence.
std::string sentence(std::string text) {
  if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  return text + ".";
}

// "corridor: LiDAR weaker", "room: both sensors good".
std::string familyHeading(const sim::FamilyInfo& family) {
  if (family.weaker == sim::WeakerSensor::kNeither) return family.name + ": both sensors good";
  return family.name + ": " + weakerSensorText(family.weaker) + " weaker";
}

struct FamilyResult {
  sim::FamilyInfo info;
  std::vector<system::BenchRow> rows;  // one per seed, then their mean when more than one
};

// The families to run, in the order of sim::families() (names checked by the option).
std::vector<sim::FamilyInfo> chosenFamilies(const std::vector<std::string>& names) {
  std::vector<sim::FamilyInfo> chosen;
  for (const sim::FamilyInfo& f : sim::families())
    if (names.empty() || std::find(names.begin(), names.end(), f.name) != names.end()) chosen.push_back(f);
  return chosen;
}

FamilyResult runFamily(const sim::FamilyInfo& family, int seeds, double duration, const std::vector<Column>& cols,
                       const std::string& config, const fs::path& work) {
  FamilyResult result{family, {}};
  for (int seed = 1; seed <= seeds; ++seed) {
    SuiteSequence s{fmt::format("{}-seed{}", family.name, seed), sim::familyOptions(family.name)};
    s.options.duration = duration;
    s.options.seed = static_cast<std::uint64_t>(seed);
    // "family-" keeps these apart from the classic suite's room and gate folders.
    const std::string dir = ensureSimulated({"family-" + s.name, s.options}, work / "sequences");
    system::BenchRow row =
        runRow(s.name, dir, cols, config, work / "runs" / fs::path(dir).filename(), system::familyAccuracyCellText);
    row.sequence = std::to_string(seed);
    result.rows.push_back(row);
  }
  if (seeds > 1) result.rows.push_back(system::meanRow(result.rows, columnNames(cols), "mean"));
  return result;
}

std::string familiesReport(const std::vector<FamilyResult>& results, const std::vector<std::string>& names,
                           const std::string& command, double duration, int seeds) {
  std::vector<system::FamilySummary> summary;
  for (const FamilyResult& r : results) {
    const std::vector<system::BenchRow> seed_rows(r.rows.begin(), r.rows.begin() + seeds);
    summary.push_back({r.info.name, weakerSensorText(r.info.weaker), r.rows.back(), seed_rows});  // back: the mean
  }
  std::string text = fmt::format(
      "### Scenario families (`lvslam bench --suite families`)\n\n"
      "Command: `{}` on {}, {}. Simulated family sequences (docs/simulator.md) of {:g} s, seed{} {}.\n\n"
      "Summary: ATE rmse (m) of the online trajectory{}; fused beats the better single mode when its online ATE is "
      "lower, by the percentage of the better single mode's ATE (a mode that fails or loses track for more than half "
      "of its frames, x, is no contender).\n\n{}",
      command, machine(), today(), duration, seeds > 1 ? "s" : "", seeds > 1 ? fmt::format("1-{}", seeds) : "1",
      seeds > 1 ? ", mean over the seeds" : "", system::familySummaryTable(summary));
  text +=
      "\nPer family, one row per seed: ATE rmse (m) of the online trajectory / of the offline refinement, and the "
      "share of camera frames whose pose vision entered; then the real-time factor (sequence seconds per wall "
      "second) of the online pipeline / of the whole run (the offline refinement included), the median latency of the online output and the peak memory of each run.\n";
  for (const FamilyResult& r : results)
    text += fmt::format("\n#### {}\n\n{}\n\nAccuracy:\n\n{}\nSpeed:\n\n{}", familyHeading(r.info),
                        sentence(r.info.purpose), system::familyAccuracyTable(r.rows, names),
                        system::familySpeedTable(r.rows, names));
  return text;
}

int runFamilies(const BenchArgs& args, const std::string& command) {
  if (!args.sequences.empty()) throw Error(args.sequences.front(), "sequence folders go with --suite classic");
  // --quick: a smoke run of every family (one seed, 15 s) unless told otherwise.
  const double duration = args.quick && !args.duration_given ? 15.0 : args.duration;
  const int seeds = args.quick ? 1 : args.seeds;
  const std::vector<Column> cols = columns(!args.no_ablations);
  const std::string config = fs::exists(args.config_path) ? args.config_path : "";
  std::vector<FamilyResult> results;
  for (const sim::FamilyInfo& family : chosenFamilies(args.families))
    results.push_back(runFamily(family, seeds, duration, cols, config, fs::path(args.work_dir)));
  const int code = publish(args, familiesReport(results, columnNames(cols), command, duration, seeds));
  std::vector<std::string> groups;
  for (const FamilyResult& r : results)
    groups.push_back(system::benchGroupJson(familyHeading(r.info), sentence(r.info.purpose), r.rows, columnNames(cols)));
  writeBenchPage(args, command, groups);
  return code;
}

// The command as the report quotes it (options that change the figures).
std::string quotedCommand(const BenchArgs& args) {
  std::string command = "lvslam bench";
  if (args.suite != "classic") command += " --suite " + args.suite;
  if (args.quick) command += " --quick";
  if (!args.families.empty()) command += " --families " + fmt::format("{}", fmt::join(args.families, ","));
  if (!args.quick || args.duration_given) command += fmt::format(" --duration {:g}", args.duration);
  if (args.no_ablations) command += " --no-ablations";
  if (args.seeds > 1) command += fmt::format(" --seeds {}", args.seeds);
  for (const std::string& s : args.sequences) command += " " + s;
  return command;
}

}  // namespace

void addBenchCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run a simulated suite in the modes lidar, visual, fused and the fused ablations; print the tables and "
               "write them into docs/benchmarks.md and bench.html beside it (bars per mode). --suite classic (the default): room, hall, gate, gate at night, "
               "room with a camera blackout and any sequence folders given, in the paper's tables. --suite families: "
               "the scenario families (lvslam simulate --family) with seeds 1..N, a table per family and a summary "
               "of whether fused beats the better single mode");
  auto args = std::make_shared<BenchArgs>();
  cmd->add_option("--suite", args->suite, "classic or families")
      ->default_val("classic")
      ->check(CLI::IsMember({"classic", "families"}));
  cmd->add_option("sequences", args->sequences, "More sequence folders (docs/sequence-format.md; classic suite)");
  cmd->add_option("--families", args->families, "Families suite: these families only, comma-separated (default all)")
      ->delimiter(',')
      ->check(CLI::IsMember(sim::familyNames()));
  CLI::Option* quick =
      cmd->add_flag("--quick", args->quick, "Families suite: a smoke run, one seed and 15 s (unless --duration)");
  CLI::Option* duration = cmd->add_option("--duration", args->duration, "Seconds of each simulated sequence")
                              ->default_val(60.0)
                              ->check(CLI::PositiveNumber);
  cmd->add_option("--work-dir", args->work_dir, "Simulated sequences and run outputs")->default_val("out/bench");
  cmd->add_option("--config", args->config_path, "Configuration of every run")->default_val("config/sim.yaml");
  cmd->add_option("--doc", args->doc_path, "Markdown file whose bench section is rewritten")->default_val("docs/benchmarks.md");
  cmd->add_flag("--no-doc", args->no_doc, "Print the tables only");
  cmd->add_flag("--no-ablations", args->no_ablations, "Modes lidar, visual and fused only");
  cmd->add_option("--seeds", args->seeds,
                  "Classic: run room, hall and gate with seeds 1..N and add their mean row; families: every family "
                  "with seeds 1..N and a mean row")
      ->default_val(1)
      ->check(CLI::Range(1, 20))
      ->excludes(quick);
  cmd->callback([&action, args, duration] {
    args->duration_given = duration->count() > 0;
    const std::string command = quotedCommand(*args);
    action = [args, command] {
      return args->suite == "families" ? runFamilies(*args, command) : runClassic(*args, command);
    };
  });
}

}  // namespace lvslam::apps

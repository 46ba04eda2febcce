// `lvslam bench`: the simulated suite (room, hall, gate, gate at night, room
// with a camera blackout) and any sequence folders given, in the modes
// lidar, visual and fused plus the ablations of the paper's contributions;
// prints the paper-style tables and writes them into docs/benchmarks.md.
// Each run is its own `lvslam run` process, so its peak memory is its own.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "command.h"
#include "lvslam/core/error.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/sim/simulate_sequence.h"
#include "lvslam/system/bench_table.h"

namespace lvslam::apps {

namespace fs = std::filesystem;

namespace {

struct BenchArgs {
  std::vector<std::string> sequences;
  double duration = 60.0;
  std::string work_dir = "out/bench";
  std::string config_path = "config/sim.yaml";
  std::string doc_path = "docs/benchmarks.md";
  bool no_doc = false;
  bool no_ablations = false;
  int seeds = 1;  // room, hall and gate with seeds 1..seeds
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
// leave the mathematics alone (docs/benchmarks.md), so one seed is one draw.
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
  cell.peak_rss_mib = summary.at("peak_rss_mib").asDouble();
  if (const auto accuracy = summary.find("accuracy"))
    cell.ate_mean_m = accuracy->at("aligned_mean_translation_error").asDouble();
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
      "Real-time factor (sequence seconds per wall second, reading included) and peak memory of each run:\n\n{}",
      command, machine(), today(), duration, system::accuracyTable(rows, names), system::speedTable(rows, names));
}

int runBench(const BenchArgs& args, const std::string& command) {
  const fs::path work(args.work_dir);
  const std::vector<Column> cols = columns(!args.no_ablations);
  std::vector<std::string> names;
  for (const Column& c : cols) names.push_back(c.name);
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
  for (const auto& [name, dir] : sequences) {
    system::BenchRow row{name, {}};
    for (const Column& c : cols) {
      std::cout << fmt::format("{:<16} {:<27}", name, c.name) << std::flush;
      // Sequences without the sensors of a mode are skipped by `run` with an error: shown as fail.
      row.cells[c.name] = runCell(dir, c, config, work / "runs" / name / c.folder);
      std::cout << system::accuracyCellText(row.cells[c.name]) << "\n";
    }
    rows.push_back(row);
  }
  if (args.seeds > 1) {
    std::vector<system::BenchRow> daylight;
    for (const system::BenchRow& row : rows)
      if (daylight_names.count(row.sequence)) daylight.push_back(row);
    rows.push_back(system::meanRow(daylight, names, fmt::format("mean, room/hall/gate x seeds 1-{}", args.seeds)));
  }
  const std::string text = report(rows, names, command, args.duration);
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

}  // namespace

void addBenchCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run the simulated suite (room, hall, gate, gate at night, room with a camera blackout) and any "
               "sequence folders given in the modes lidar, visual, fused and the fused ablations; print the "
               "paper-style tables and write them into docs/benchmarks.md");
  auto args = std::make_shared<BenchArgs>();
  cmd->add_option("sequences", args->sequences, "More sequence folders (docs/sequence-format.md)");
  cmd->add_option("--duration", args->duration, "Seconds of each simulated sequence")->default_val(60.0)->check(CLI::PositiveNumber);
  cmd->add_option("--work-dir", args->work_dir, "Simulated sequences and run outputs")->default_val("out/bench");
  cmd->add_option("--config", args->config_path, "Configuration of every run")->default_val("config/sim.yaml");
  cmd->add_option("--doc", args->doc_path, "Markdown file whose bench section is rewritten")->default_val("docs/benchmarks.md");
  cmd->add_flag("--no-doc", args->no_doc, "Print the tables only");
  cmd->add_flag("--no-ablations", args->no_ablations, "Modes lidar, visual and fused only");
  cmd->add_option("--seeds", args->seeds, "Run room, hall and gate with seeds 1..N and add their mean row")
      ->default_val(1)
      ->check(CLI::Range(1, 20));
  cmd->callback([&action, args] {
    // The command as the report quotes it (options that change the figures).
    std::string command = fmt::format("lvslam bench --duration {:g}", args->duration);
    if (args->no_ablations) command += " --no-ablations";
    if (args->seeds > 1) command += fmt::format(" --seeds {}", args->seeds);
    for (const std::string& s : args->sequences) command += " " + s;
    action = [args, command] { return runBench(*args, command); };
  });
}

}  // namespace lvslam::apps

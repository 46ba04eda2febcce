// The fault matrix: a short clean simulated sequence, broken in one way
// per test, run through the real binary. Each case checks the exit code (0
// ok, 1 no result, 2 bad input), the one stderr line naming the file and the
// line or key, and what was written. Input faults run `--mode lidar`: they
// are about reading, not fusion, and it keeps the suite fast.
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <regex>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "apps/clean_sequence.h"
#include "apps/run_lvslam.h"
#include "support/temp_dir.h"
#include "system/sim_cache.h"

namespace lvslam {
namespace {

namespace fs = std::filesystem;
using testing::cleanSequence;
using testing::lines;
using testing::RunResult;
using testing::slurpBinary;
using testing::TempDir;

// The input faults do not depend on the HTML report: a build without its
// JavaScript assets says so in one more stderr line, dropped here.
RunResult runWithoutReportNote(const TempDir& dir, const std::string& args, const std::string& prefix = "") {
  RunResult r = testing::runLvslam(dir, args, prefix);
  r.err = std::regex_replace(r.err, std::regex("(^|\n)warning: [^\n]*report.html not written:[^\n]*\n"), "$1");
  return r;
}

// Runs a command as user nobody when the test runs as root (root reads what
// permissions forbid); the folder must then be open to nobody.
std::string asUnprivileged(const TempDir& dir) {
  if (::geteuid() != 0) return "";
  fs::permissions(dir.path(), fs::perms::all);
  return "setpriv --reuid=65534 --regid=65534 --clear-groups ";
}

// The clean sequence with some files replaced (path below `dir` -> text),
// then `lvslam <args>`.
RunResult runEdited(const TempDir& dir, std::initializer_list<std::pair<const char*, std::string>> files,
                    const std::string& args) {
  cleanSequence(dir);
  for (const auto& [path, text] : files) dir.write(path, text);
  return runWithoutReportNote(dir, args);
}

void expectOneErrorLine(const RunResult& r, int code, const std::string& names) {
  EXPECT_EQ(r.exit_code, code) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
}

TEST(FaultMatrix, CleanSequenceRunsAndWritesItsOutputs) {
  TempDir dir;
  const RunResult r = runWithoutReportNote(dir, "run --sequence " + cleanSequence(dir) + " --mode lidar --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(fs::exists(dir.path() / "out/trajectory.tum"));
}

TEST(FaultMatrix, FileNameTooLongInTimesNamesTheLine) {
  TempDir dir;
  cleanSequence(dir);
  const std::string long_name = std::string(300, 'n') + ".bin";
  dir.write("seq/lidar/times.txt", slurpBinary(dir.file("seq/lidar/times.txt")) + "1800000000.0 " + long_name + "\n");
  const int line = lines(slurpBinary(dir.file("seq/lidar/times.txt")));
  const RunResult r = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out");
  expectOneErrorLine(r, 2, "lidar/times.txt:" + std::to_string(line) + ": cannot access");
  EXPECT_NE(r.err.find("too long"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(FaultMatrix, SymlinkLoopAsTheSequenceIsNamed) {
  TempDir dir;
  fs::create_symlink("loop", dir.path() / "loop");
  const RunResult r = runWithoutReportNote(dir, "run --sequence loop --mode lidar --out out");
  expectOneErrorLine(r, 2, "loop: cannot access");
  EXPECT_NE(r.err.find("symbolic links"), std::string::npos) << r.err;
}

// `lvslam run --mode lidar` on the clean sequence with `folder` closed to
// the user that runs it.
RunResult runWithFolderClosed(const TempDir& dir, const std::string& folder) {
  cleanSequence(dir);
  const std::string prefix = asUnprivileged(dir);
  fs::permissions(dir.path() / folder, fs::perms::none);
  const RunResult r = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out", prefix);
  fs::permissions(dir.path() / folder, fs::perms::owner_all);
  return r;
}

TEST(FaultMatrix, UnreadableSequenceFolderIsNamed) {
  TempDir dir;
  const RunResult r = runWithFolderClosed(dir, "seq");
  expectOneErrorLine(r, 2, "seq/sequence.yaml: cannot access");
  EXPECT_NE(r.err.find("Permission denied"), std::string::npos) << r.err;
}

TEST(FaultMatrix, UnreadableLidarFolderIsNotCalledMissing) {
  TempDir dir;
  const RunResult r = runWithFolderClosed(dir, "seq/lidar");
  expectOneErrorLine(r, 2, "seq/lidar/times.txt: cannot access");
  EXPECT_NE(r.err.find("Permission denied"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("not found"), std::string::npos) << r.err;
}

TEST(FaultMatrix, ConfigWithANonScalarKeyNamesFileAndLine) {
  TempDir dir;
  const RunResult r = runEdited(dir, {{"bad.yaml", "system:\n  ? [a, b]\n  : 1\n"}},
                                "run --sequence seq --mode lidar --config bad.yaml --out out");
  expectOneErrorLine(r, 2, "bad.yaml:2: key 'system'");
}

TEST(FaultMatrix, EmptyCameraTimesInFusedModeRunsLidarWithAWarning) {
  TempDir dir;
  const RunResult r = runEdited(dir, {{"seq/camera/times.txt", ""}}, "run --sequence seq --mode fused --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("camera/times.txt: lists no image"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("running mode lidar instead of fused"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << "warnings belong on stderr: " << r.out;
  EXPECT_GT(lines(slurpBinary(dir.file("out/trajectory.tum"))), 20);
}

TEST(FaultMatrix, EmptyCameraTimesInVisualModeIsNoResult) {
  TempDir dir;
  const RunResult r = runEdited(dir, {{"seq/camera/times.txt", ""}}, "run --sequence seq --mode visual --out out");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("no result: mode visual needs camera data"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out/trajectory.tum"));
}

TEST(FaultMatrix, SequenceWithoutDataIsNoResult) {
  TempDir dir;
  const RunResult r =
      runEdited(dir, {{"seq/camera/times.txt", ""}, {"seq/lidar/times.txt", ""}}, "run --sequence seq --out out");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("no result: the recording has neither camera images nor LiDAR scans"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out/trajectory.tum"));
}

// camera/times.txt with `seconds` added from line `from` on.
std::string shiftedCameraTimes(const TempDir& dir, int from, double seconds) {
  std::istringstream in(slurpBinary(dir.file("seq/camera/times.txt")));
  std::string out, line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n >= from) {
      std::istringstream fields(line);
      double t = 0.0;
      std::string file;
      fields >> t >> file;
      line = fmt::format("{:.9f} {}", t + seconds, file);
    }
    out += line + "\n";
  }
  return out;
}

TEST(FaultMatrix, OneSensorsClockJumpIsNamedNotCalledADropOut) {
  TempDir dir;
  cleanSequence(dir);
  dir.write("seq/camera/times.txt", shiftedCameraTimes(dir, 20, 100.0));
  const RunResult r = runWithoutReportNote(dir, "run --sequence seq --out out");
  expectOneErrorLine(r, 2, "seq/camera/times.txt:20: time stamp");
  EXPECT_NE(r.err.find("jumps by 100.0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("clock jumped, not a drop-out"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(FaultMatrix, ALidarDropOutStillRuns) {
  TempDir dir;
  sim::SimOptions options;
  options.scenario = "room";
  options.duration = 3.0;
  options.lidar_dropout = sim::TimeInterval{1.0, 2.0};
  fs::copy(testing::cachedSimulation("faults-room-3s-lidar-dropout-1-2", options), dir.path() / "seq",
           fs::copy_options::recursive);
  const RunResult r = runWithoutReportNote(dir, "run --sequence seq --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("lidar/times.txt: time jumps by"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(a drop-out"), std::string::npos) << r.err;
  EXPECT_GT(lines(slurpBinary(dir.file("out/trajectory.tum"))), 40);
}

TEST(FaultMatrix, AReusedOutputFolderKeepsNoEarlierRunsFiles) {
  TempDir dir;
  cleanSequence(dir);
  dir.write("out/trajectory.tum", "stale\n");
  dir.write("out/subsystems/visual_map_7.tum", "stale\n");
  dir.write("out/subsystems/notes.txt", "the user's own\n");
  const RunResult r = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(slurpBinary(dir.file("out/trajectory.tum")), "stale\n");
  EXPECT_FALSE(fs::exists(dir.path() / "out/subsystems/visual_map_7.tum"));
  EXPECT_TRUE(fs::exists(dir.path() / "out/subsystems/notes.txt"));
  // A later run without result leaves no trajectory that could pass for its own.
  dir.write("seq/lidar/times.txt", "");
  EXPECT_EQ(runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out").exit_code, 1);
  EXPECT_FALSE(fs::exists(dir.path() / "out/trajectory.tum"));
  EXPECT_FALSE(fs::exists(dir.path() / "out/stats.json"));
}

TEST(FaultMatrix, AnOutputFolderThatIsAFileIsNamed) {
  TempDir dir;
  const RunResult r = runEdited(dir, {{"out", "a file\n"}}, "run --sequence seq --mode lidar --out out");
  expectOneErrorLine(r, 2, "out: the output folder is not a folder");
  EXPECT_EQ(slurpBinary(dir.file("out")), "a file\n");
}

// ---- Damaged sensor files: each named in one line, or a documented recovery.

// The clean sequence with the bytes of `file` (below seq/) replaced by what
// `damage` makes of them.
template <typename Damage>
RunResult runDamaged(const TempDir& dir, const std::string& file, Damage damage, const std::string& mode) {
  cleanSequence(dir);
  const std::string path = dir.file("seq/" + file);
  dir.write("seq/" + file, damage(slurpBinary(path)));
  return runWithoutReportNote(dir, "run --sequence seq --mode " + mode + " --out out");
}

std::string half(const std::string& bytes) { return bytes.substr(0, bytes.size() / 2); }
std::string nothing(const std::string&) { return ""; }
std::string overwritten(std::string bytes) { return bytes.replace(bytes.size() / 2, 8, 8, '\xff'); }

TEST(FaultMatrix, TruncatedScanNamesTheFileAndItsSize) {
  TempDir dir;
  const RunResult r = runDamaged(dir, "lidar/000005.bin", [](const std::string& b) { return b.substr(0, 1000); }, "lidar");
  expectOneErrorLine(r, 2, "seq/lidar/000005.bin: size 1000 bytes is not a multiple of the record size 24");
}

TEST(FaultMatrix, EmptyScanIsReadAsNoPointsWithAWarning) {
  TempDir dir;
  const RunResult r = runDamaged(dir, "lidar/000005.bin", nothing, "lidar");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("seq/lidar/000005.bin: empty scan file"), std::string::npos) << r.err;
  EXPECT_GT(lines(slurpBinary(dir.file("out/trajectory.tum"))), 40);
}

TEST(FaultMatrix, MissingScanAndImageNameTheTimesLine) {
  TempDir dir;
  cleanSequence(dir);
  fs::remove(dir.path() / "seq/lidar/000005.bin");
  expectOneErrorLine(runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out"), 2,
                     "seq/lidar/times.txt:7: file 'seq/lidar/000005.bin' not found");
  TempDir dir2;
  cleanSequence(dir2);
  fs::remove(dir2.path() / "seq/camera/000005.png");
  expectOneErrorLine(runWithoutReportNote(dir2, "run --sequence seq --mode visual --out out"), 2,
                     "seq/camera/times.txt:7: file 'seq/camera/000005.png' not found");
}

TEST(FaultMatrix, TruncatedImageIsOneLineNamingTheByte) {
  TempDir dir;
  const RunResult r = runDamaged(dir, "camera/000005.png", half, "visual");
  expectOneErrorLine(r, 2, "seq/camera/000005.png: damaged PNG: the file ends at byte");
  EXPECT_EQ(r.err.find("libpng"), std::string::npos) << r.err;
}

TEST(FaultMatrix, OverwrittenImageIsOneLineNamingTheChunk) {
  TempDir dir;
  const RunResult r = runDamaged(dir, "camera/000005.png", overwritten, "visual");
  expectOneErrorLine(r, 2, "seq/camera/000005.png: damaged PNG: chunk 'IDAT' at byte");
  EXPECT_EQ(r.err.find("libpng"), std::string::npos) << r.err;
}

TEST(FaultMatrix, EmptyImageIsNamed) {
  TempDir dir;
  expectOneErrorLine(runDamaged(dir, "camera/000005.png", nothing, "visual"), 2,
                     "seq/camera/000005.png: empty file (0 bytes)");
}

// ---- A recording cut off as a killed recorder leaves it: the
// run goes up to the cut, writes everything it has, then names the fault in
// one line (exit 2).

// The file named on the last line of a times.txt.
std::string lastFileOf(const std::string& times) {
  const std::size_t end = times.find_last_not_of('\n');
  const std::size_t start = times.rfind('\n', end) + 1;
  const std::string line = times.substr(start, end + 1 - start);
  return line.substr(line.find(' ') + 1);
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The clean sequence run, then the same with the last file of `sensor` cut in
// half (both deterministic): the cut run's result and file, both runs' poses.
struct CutRun {
  RunResult result;
  std::string cut_file;
  std::vector<std::string> clean_poses, poses;
  std::vector<std::string> clean_frames, frames;  // stats_frames.jsonl, one record a line
};

CutRun runCutAtTheEnd(const TempDir& dir, const std::string& sensor) {
  cleanSequence(dir);
  const std::string args = " --mode lidar --deterministic";
  EXPECT_EQ(runWithoutReportNote(dir, "run --sequence seq --out clean" + args).exit_code, 0);
  CutRun cut;
  cut.cut_file = "seq/" + sensor + "/" + lastFileOf(slurpBinary(dir.file("seq/" + sensor + "/times.txt")));
  dir.write(cut.cut_file, half(slurpBinary(dir.file(cut.cut_file))));
  cut.result = runWithoutReportNote(dir, "run --sequence seq --out out" + args);
  cut.clean_poses = linesOf(slurpBinary(dir.file("clean/trajectory.tum")));
  cut.poses = linesOf(slurpBinary(dir.file("out/trajectory.tum")));
  cut.clean_frames = linesOf(slurpBinary(dir.file("clean/stats_frames.jsonl")));
  cut.frames = linesOf(slurpBinary(dir.file("out/stats_frames.jsonl")));
  // stats.json's summary says where the run stopped; the maps are written.
  const std::string stats = slurpBinary(dir.file("out/stats.json"));
  EXPECT_NE(stats.find("\"stopped\": {\"where\": \"" + cut.cut_file + "\""), std::string::npos) << stats.substr(0, 2000);
  EXPECT_TRUE(fs::exists(dir.path() / "out/map.ply"));
  EXPECT_TRUE(fs::exists(dir.path() / "out/trajectory_refined.tum"));
  EXPECT_NE(cut.result.out.find("the recording could not be read after t = "), std::string::npos) << cut.result.out;
  return cut;
}

TEST(FaultMatrix, ACutLastImageKeepsEveryPoseBeforeIt) {
  TempDir dir;
  const CutRun cut = runCutAtTheEnd(dir, "camera");
  expectOneErrorLine(cut.result, 2, cut.cut_file + ": damaged PNG: the file ends at byte");
  // Every frame before the cut image has its pose; the online output is
  // causal, so they are the clean run's poses but the last frame's.
  ASSERT_GT(cut.clean_poses.size(), 40u);
  EXPECT_EQ(cut.poses, std::vector<std::string>(cut.clean_poses.begin(), cut.clean_poses.end() - 1));
  // So are the per-frame records streamed beside them: one per frame up to the cut.
  ASSERT_EQ(cut.clean_frames.size(), cut.clean_poses.size());
  EXPECT_EQ(cut.frames, std::vector<std::string>(cut.clean_frames.begin(), cut.clean_frames.end() - 1));
}

TEST(FaultMatrix, ACutLastScanKeepsThePosesBeforeIt) {
  TempDir dir;
  const CutRun cut = runCutAtTheEnd(dir, "lidar");
  expectOneErrorLine(cut.result, 2, cut.cut_file + ": size ");
  // The frames after the last whole scan have no sweep to be posed in; every
  // pose written is the clean run's up to the frames the last sweep fixed.
  ASSERT_GT(cut.poses.size(), cut.clean_poses.size() - 5) << "frames of the last sweep at most are missing";
  ASSERT_LT(cut.poses.size(), cut.clean_poses.size());
  const std::size_t settled = cut.poses.size() - 2;  // the last frames' poses came from the shorter run's end
  EXPECT_EQ(std::vector<std::string>(cut.poses.begin(), cut.poses.begin() + settled),
            std::vector<std::string>(cut.clean_poses.begin(), cut.clean_poses.begin() + settled));
  // Each frame's streamed record is there with its pose, the same as the clean run's.
  ASSERT_GE(cut.frames.size(), cut.poses.size());
  EXPECT_EQ(std::vector<std::string>(cut.frames.begin(), cut.frames.begin() + settled),
            std::vector<std::string>(cut.clean_frames.begin(), cut.clean_frames.begin() + settled));
}

// Every third point of scans 3..9 set to `value` (x, y and z).
std::string pointsSetTo(std::string bytes, float value) {
  constexpr std::size_t kRecord = 6 * sizeof(float);  // x y z intensity time ring
  for (std::size_t at = 0; at + kRecord <= bytes.size(); at += 3 * kRecord)
    for (int i = 0; i < 3; ++i) std::memcpy(&bytes[at + i * sizeof(float)], &value, sizeof(float));
  return bytes;
}

// The online "aligned mean translation error: X m" of lvslam run's output.
double onlineError(const std::string& out) {
  const std::string key = "aligned mean translation error: ";
  const std::size_t at = out.find(key);
  return at == std::string::npos ? 1e9 : std::stod(out.substr(at + key.size()));
}

TEST(FaultMatrix, NonFiniteAndHugePointsAreDroppedAsInvalidReturns) {
  for (const float value : {std::nanf(""), std::numeric_limits<float>::infinity(), 1e30f, -3e38f}) {
    TempDir dir;
    cleanSequence(dir);
    for (int scan = 3; scan <= 9; ++scan) {
      const std::string path = dir.file(fmt::format("seq/lidar/{:06d}.bin", scan));
      dir.write(fmt::format("seq/lidar/{:06d}.bin", scan), pointsSetTo(slurpBinary(path), value));
    }
    const RunResult r = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out");
    ASSERT_EQ(r.exit_code, 0) << value << ": " << r.err;
    EXPECT_LT(onlineError(r.out), 0.02) << value << ": " << r.out;
  }
}

TEST(FaultMatrix, DuplicateStampNamesTheLine) {
  TempDir dir;
  cleanSequence(dir);
  std::string times = slurpBinary(dir.file("seq/lidar/times.txt"));
  const std::size_t line5 = times.find("000003.bin");  // line 5; give it line 4's stamp
  const std::size_t line4 = times.rfind('\n', times.rfind('\n', line5) - 1) + 1;
  times.replace(times.rfind('\n', line5) + 1, 20, times.substr(line4, 20));
  dir.write("seq/lidar/times.txt", times);
  expectOneErrorLine(runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out"), 2,
                     "seq/lidar/times.txt:5: time stamp");
}

TEST(FaultMatrix, MalformedSequenceYamlAndGroundTruthAreNamed) {
  TempDir dir;
  expectOneErrorLine(runEdited(dir, {{"seq/sequence.yaml", "format: lvslam-sequence/1\ncamera: [\n"}},
                               "run --sequence seq --mode lidar --out out"),
                     2, "seq/sequence.yaml: malformed YAML at line");
  TempDir dir2;
  cleanSequence(dir2);
  std::string gt = slurpBinary(dir2.file("seq/groundtruth.txt"));
  const std::size_t line3 = gt.find('\n', gt.find('\n') + 1) + 1;
  gt.insert(line3 + 2, "x");
  dir2.write("seq/groundtruth.txt", gt);
  expectOneErrorLine(runWithoutReportNote(dir2, "run --sequence seq --mode lidar --out out"), 2, "seq/groundtruth.txt:3:");
}

TEST(FaultMatrix, UnwritableOutputIsNamedBeforeTheRun) {
  TempDir dir;
  cleanSequence(dir);
  const std::string prefix = asUnprivileged(dir);
  fs::create_directories(dir.path() / "locked");
  fs::permissions(dir.path() / "locked", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::others_read |
                                             fs::perms::others_exec);
  const RunResult r = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out locked", prefix);
  expectOneErrorLine(r, 2, "locked: cannot write in the output folder: Permission denied");
  EXPECT_EQ(r.out.find("lidar subsystem"), std::string::npos) << "no run before the check: " << r.out;
  const RunResult below = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out locked/out", prefix);
  expectOneErrorLine(below, 2, "locked/out: cannot create the output folder: Permission denied");
}

TEST(FaultMatrix, AMisspeltPointFieldIsWarnedAboutOnce) {
  TempDir dir;
  cleanSequence(dir);
  std::string yaml = slurpBinary(dir.file("seq/sequence.yaml"));
  yaml.replace(yaml.find("time, ring"), 4, "tiem");
  dir.write("seq/sequence.yaml", yaml);
  const RunResult r = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines(r.err), 2) << r.err;
  EXPECT_NE(r.err.find("seq/sequence.yaml: key 'lidar.point_fields': unknown field 'tiem' is skipped; did you mean "
                       "'time'?"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("no per-point 'time'"), std::string::npos) << r.err;
}

TEST(FaultMatrix, ImplausibleFocalLengthsAreWarnedAbout) {
  for (const char* fx : {"1e-9", "1e300"}) {
    TempDir dir;
    cleanSequence(dir);
    std::string yaml = slurpBinary(dir.file("seq/sequence.yaml"));
    yaml.replace(yaml.find("617.971"), 7, fx);
    dir.write("seq/sequence.yaml", yaml);
    const RunResult r = runWithoutReportNote(dir, "run --sequence seq --mode lidar --out out");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("seq/sequence.yaml: key 'camera.intrinsics': fx = "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("implausible"), std::string::npos) << r.err;
  }
}

TEST(FaultMatrix, FolderGivenAsTheEstimateIsNamedAsSuch) {
  TempDir dir;
  cleanSequence(dir);
  const RunResult r = runWithoutReportNote(dir, "eval --gt seq/groundtruth.txt --est seq");
  expectOneErrorLine(r, 2, "seq: is a folder, not a file");
}

}  // namespace
}  // namespace lvslam

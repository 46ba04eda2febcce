#pragma once
// The online part of each frame's stats.json record (subsystem in use,
// gated factors, latency), and a stream of it: stats_frames.jsonl, one JSON
// object a line, appended and flushed as the online output makes each frame,
// so a run stopped by a fault or killed leaves the records made so far.
// stats.json, written at the end, holds the same fields per frame and more.
#include <fstream>
#include <string>

#include "lvslam/eval/json_writer.h"
#include "lvslam/system/online/online_output.h"

namespace lvslam::system {

// The frame's online fields, in stats.json's order (latency only with timings).
eval::JsonObject onlineFrameJson(const FrameOutput& frame, bool timings);

class FrameStatsStream {
 public:
  // Throws lvslam::Error naming the file when it cannot be written.
  FrameStatsStream(const std::string& path, bool timings);
  void add(const FrameOutput& frame);

 private:
  std::string path_;
  std::ofstream out_;
  bool timings_;
};

}  // namespace lvslam::system

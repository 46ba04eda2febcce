#pragma once
// One self-overwriting status line on stderr while a run is going, only when
// stderr is a terminal (logs and CI get none of it).
#include <chrono>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace lvslam::apps {

class ProgressLine {
 public:
  ProgressLine() : enabled_(isatty(STDERR_FILENO) != 0) {}
  ~ProgressLine() { finish(); }

  // At most ten updates a second reach the terminal.
  void update(const std::string& text) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    std::fprintf(stderr, "\r\033[K%s", text.c_str());
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\r\033[K");
    shown_ = false;
  }

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace lvslam::apps

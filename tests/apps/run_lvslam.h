#pragma once
// Runs the real `lvslam` binary in a test folder and keeps what it said:
// the end-to-end tests check exit codes, stderr lines and written files.
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "support/temp_dir.h"

namespace lvslam::testing {

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

// `prefix` goes before the binary (e.g. "setpriv ... " to run as another user).
inline RunResult runLvslam(const TempDir& dir, const std::string& args, const std::string& prefix = "") {
  const std::string out = dir.file("stdout.txt"), err = dir.file("stderr.txt");
  const std::string cmd = std::string("cd '") + dir.path().string() + "' && " + prefix + "'" + LVSLAM_BINARY + "' " +
                          args + " > '" + out + "' 2> '" + err + "'";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;  // -1: killed by a signal (a crash)
  r.out = slurpBinary(out);
  r.err = slurpBinary(err);
  return r;
}

inline int lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

}  // namespace lvslam::testing

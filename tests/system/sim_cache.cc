#include "system/sim_cache.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "lvslam/sim/simulate_sequence.h"

namespace lvslam::testing {

namespace {

// An exclusive flock on a file, released when destroyed (or if the process dies).
class FileLock {
 public:
  explicit FileLock(const std::string& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw std::runtime_error("cannot open the lock file " + path);
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) throw std::runtime_error("cannot lock " + path);
  }
  ~FileLock() { ::close(fd_); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

std::string cachedSimulation(const std::string& name, const sim::SimOptions& options) {
  namespace fs = std::filesystem;
  const fs::path cache(LVSLAM_TEST_CACHE_DIR);
  fs::create_directories(cache);
  const fs::path done = cache / name;
  const FileLock lock((cache / (name + ".lock")).string());
  sim::simulateSequenceOnce(options, done.string());
  return done.string();
}

sim::SimOptions roomSimulation(double duration_s, int seed, double speed_scale) {
  sim::SimOptions o;
  o.scenario = "room";
  o.duration = duration_s;
  o.seed = seed;
  o.speed_scale = speed_scale;
  return o;
}

std::string cachedRoom(double duration_s, int seed, double speed_scale) {
  std::ostringstream name;
  name << "room-" << duration_s << "s-seed" << seed;
  if (speed_scale != 1.0) name << "-speed" << speed_scale;
  return cachedSimulation(name.str(), roomSimulation(duration_s, seed, speed_scale));
}

}  // namespace lvslam::testing

#pragma once
// Bad or dropped input on the node's topics, counted per kind and logged
// once per kind (a driver that sends one bad message sends thousands; the
// log must stay readable and the count must stay visible: in the
// diagnostics and in the shutdown summary).
#include <functional>
#include <map>
#include <mutex>
#include <string>

namespace lvslam::ros_node {

class InputProblems {
 public:
  using Sink = std::function<void(const std::string&)>;
  explicit InputProblems(Sink warn) : warn_(std::move(warn)) {}

  // `kind`: a short stable name ("empty cloud"); `detail`: this case.
  void report(const std::string& kind, const std::string& detail) {
    std::lock_guard lock(mutex_);
    if (counts_[kind]++ == 0) warn_(kind + ": " + detail + " (dropped; further cases are counted, not logged)");
  }
  std::map<std::string, std::size_t> counts() const {
    std::lock_guard lock(mutex_);
    return counts_;
  }

 private:
  Sink warn_;
  mutable std::mutex mutex_;
  std::map<std::string, std::size_t> counts_;
};

}  // namespace lvslam::ros_node

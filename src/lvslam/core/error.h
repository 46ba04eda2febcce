#pragma once
// lvslam::Error: the one exception type for bad input. It carries where the
// problem is (a file, a file:line, a YAML key) and why, so apps/ can print one
// line and exit with code 2.
#include <stdexcept>
#include <string>
#include <utility>

namespace lvslam {

class Error : public std::runtime_error {
 public:
  Error(std::string where, std::string why)
      : std::runtime_error(where.empty() ? why : where + ": " + why),
        where_(std::move(where)),
        why_(std::move(why)) {}

  const std::string& where() const { return where_; }
  const std::string& why() const { return why_; }

 private:
  std::string where_;
  std::string why_;
};

}  // namespace lvslam

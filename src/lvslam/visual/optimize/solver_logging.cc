#include "lvslam/visual/optimize/solver_logging.h"

#include <glog/logging.h>

namespace lvslam::visual {

void quietSolverLogging() {
  FLAGS_logtostderr = true;  // never log files in /tmp
  FLAGS_minloglevel = google::GLOG_ERROR;
  if (!google::IsGoogleLoggingInitialized()) google::InitGoogleLogging("lvslam");
}

}  // namespace lvslam::visual

#pragma once
// Ceres reports through glog; uninitialised, glog prints a warning banner and
// every solver warning (e.g. a failed Cholesky step, which LM recovers from)
// on stderr. This initialises glog once, logging to stderr and errors only.
// glog's state is process-wide by its design; calling this again is a no-op.
namespace lvslam::visual {

void quietSolverLogging();

}  // namespace lvslam::visual

#pragma once
// What loop closure reports: the `loop` section of stats.json (the
// keyframes, every loop candidate a keyframe found with its figures:
// descriptor, ICP, the graph's weight, and why it was rejected; how far the
// graph moved the keyframes) and one line for the console.
#include <string>

#include "lvslam/loop/loop_closure.h"

namespace lvslam::system {

std::string loopJson(const loop::LoopClosureResult& result);
// `applied`: as the output applied it (SystemOutput::loop); `live`: as the run made it.
std::string formatLoopSummary(const loop::LoopClosureResult& applied, const loop::LoopClosureResult& live);
// One line: where the run sits in the saved map (--map-in), or that it does not.
std::string formatMapLocalization(const loop::MapLocalization& localization);

}  // namespace lvslam::system

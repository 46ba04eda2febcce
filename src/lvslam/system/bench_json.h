#pragma once
// The figures of a `lvslam bench` table as JSON, for bench.html (one group
// per table: the classic suite, or one scenario family).
#include <string>
#include <vector>

#include "lvslam/system/bench_table.h"

namespace lvslam::system {

// {"name", "note", "columns": [...], "rows": [{"name", "cells": {column: {figures}}}]};
// a figure a cell lacks is left out.
std::string benchGroupJson(const std::string& name, const std::string& note, const std::vector<BenchRow>& rows,
                           const std::vector<std::string>& columns);

}  // namespace lvslam::system

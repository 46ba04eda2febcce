#pragma once
// This process's memory as the operating system sees it.

namespace lvslam {

// Peak resident memory of this process (VmHWM), MiB; 0 when unknown.
double peakResidentMiB();

// Hands the free pages of every malloc arena back to the system (glibc's
// malloc_trim; nothing elsewhere). The pipeline's threads leave their
// arenas' freed memory resident after they end, where the main thread's
// later allocations cannot reuse it.
void releaseFreedMemory();

}  // namespace lvslam

#pragma once
// `shadowlab bench --soft-reference`: what the soft reference (reference/soft_visibility.h) costs on the CPU for the
// settings' first shadow-casting light at its size (lights.N.size > 0) and reference.softRays, over the main view as
// `measure` sees it (the accuracy G-buffer, the hard verdicts). The same pixels are traced twice: one rtcOccluded1
// query per ray (how the reference was first traced) and a pixel's rays together through Embree's stream query
// (what `measure` uses); prints each one's time and rays per second, the speed-up, and how far the two V differ
// (max |dV| and the pixels that differ: the soft metrics read V alone, so equal V leaves them unchanged).
#include "cli/bench_command.h"

namespace shadowlab::cli {

int runBenchSoftReference(const BenchOptions& options);

}  // namespace shadowlab::cli

#pragma once
// The case functions, one per file (case_NN_*.cpp); hard_case_list.cpp lists them with their titles.
#include "hardcases/hard_case.h"

namespace shadowlab::hardcases {

void runPoleSweep(CaseContext& context, CaseResult& result);            // 1
void runGrazingClamp(CaseContext& context, CaseResult& result);         // 2
void runLargeWorld(CaseContext& context, CaseResult& result);           // 3
void runPrecisionPerFormat(CaseContext& context, CaseResult& result);   // 4
void runReversedZ(CaseContext& context, CaseResult& result);            // 5
void runBorderTexels(CaseContext& context, CaseResult& result);         // 6
void runShimmer(CaseContext& context, CaseResult& result);              // 7
void runSpotAliasing(CaseContext& context, CaseResult& result);         // 8
void runCubeSeams(CaseContext& context, CaseResult& result);            // 9
void runThinCasters(CaseContext& context, CaseResult& result);          // 10
void runAlphaCutoffs(CaseContext& context, CaseResult& result);         // 11
void runPancaking(CaseContext& context, CaseResult& result);            // 12
void runMirroredInstances(CaseContext& context, CaseResult& result);    // 13
void runDegenerateLight(CaseContext& context, CaseResult& result);      // 14
void runDegenerateResolution(CaseContext& context, CaseResult& result); // 15
void runDegenerateGeometry(CaseContext& context, CaseResult& result);   // 16
void runScaleExtremes(CaseContext& context, CaseResult& result);        // 17
void runCascadeSplits(CaseContext& context, CaseResult& result);        // 18
void runCascadeSeams(CaseContext& context, CaseResult& result);         // 19
void runStaleDepthBounds(CaseContext& context, CaseResult& result);     // 20

}  // namespace shadowlab::hardcases

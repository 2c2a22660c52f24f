#pragma once
// `shadowlab hardcases`: runs the cases of ../shared/HARD_CASES.md (renderer/hardcases), prints one row per
// sub-check, writes the pictures and the JSON, exits non-zero when a case fails.
#include <string>
#include <vector>

namespace shadowlab::cli {

struct HardCasesOptions {
    std::vector<int> cases;  // --case N (repeatable); empty = every case
    bool quick = false;
    std::string json;
    std::string outDir;
    std::string sharedScenes;  // --scenes DIR; default: <shipped data>/shared-scenes (a build tree's link to it)
};

int runHardCases(const HardCasesOptions& options);

}  // namespace shadowlab::cli

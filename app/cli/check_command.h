#pragma once
// `shadowlab check`: a CI gate. Runs cases (renderer/accuracy/check_case.h: a case file, or one case from flags),
// measures each like `measure` does (every casting light alone, then the whole picture; flicker only when a flicker
// limit is set), prints one line per case with each figure beside its limit, and writes a JUnit XML file with each
// case's figures and its overlay PNG.
// Exit code: 0 every case passed; 1 a limit was broken; 2 anything that stops the gate from judging (a bad case file
// or flag, a case that could not be measured, an output that could not be written).
#include "accuracy/check_case.h"

#include <string>
#include <vector>

namespace shadowlab::cli {

inline constexpr int kCheckLimitBroken = 1;
inline constexpr int kCheckBadInput = 2;

struct CheckOptions {
    std::string file;                    // CASES.json; "" = the one case of the flags
    CheckCase flagCase;                  // --scene, --preset, --set, --width, --height, the limits, --motion ...
    std::vector<std::string> caseFlags;  // the case flags given (refused beside a case file)
    std::string motion;                  // --motion as typed ("" = not given)
    double step = 0.0;                   // --step (flagCase.step is set when it is given)
    std::string junit;                   // --junit out.xml
    std::string outDir;                  // --out-dir: the overlays; default with --junit: <junit>-overlays/
};

int runCheck(const CheckOptions& options);

}  // namespace shadowlab::cli

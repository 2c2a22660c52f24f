#include "hardcases/cases.h"

namespace shadowlab::hardcases {

const std::vector<HardCase>& hardCaseList() {
    static const std::vector<HardCase> list = {
        {1, "light direction parallel to the lookAt up vector (pole sweep)", runPoleSweep},
        {2, "grazing light and the slope-scaled bias blowing up (clamp)", runGrazingClamp},
    };
    return list;
}

}  // namespace shadowlab::hardcases

#include "shading/cascade_tints.h"

#include <cstdio>

namespace shadowlab {

glm::vec3 cascadeTint(int index) {
    const int n = int(kCascadeTints.size());
    return kCascadeTints[std::size_t(((index % n) + n) % n)];
}

std::string cascadeTintsDefine() {
    std::string text = "CASCADE_TINTS vec3[" + std::to_string(kCascadeTints.size()) + "](";
    for (std::size_t i = 0; i < kCascadeTints.size(); ++i) {
        char colour[96];
        std::snprintf(colour, sizeof colour, "%svec3(%.6f, %.6f, %.6f)", i ? ", " : "", double(kCascadeTints[i].r),
                      double(kCascadeTints[i].g), double(kCascadeTints[i].b));
        text += colour;
    }
    return text + ")";
}

}  // namespace shadowlab

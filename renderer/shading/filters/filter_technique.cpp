#include "shading/filters/filter_technique.h"

#include <stdexcept>

namespace shadowlab {

const FilterTechnique& filterTechnique(FilterKind kind) {
    for (const FilterTechnique* technique : {&pointFilter(), &hardware2x2Filter(), &pcfFilter(), &poissonFilter()})
        if (technique->kind == kind) return *technique;
    throw std::logic_error("no filter technique for FilterKind " + std::to_string(int(kind)));
}

}  // namespace shadowlab

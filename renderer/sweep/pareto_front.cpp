#include "sweep/pareto_front.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

std::vector<std::size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error) {
    const std::size_t n = std::min(cost.size(), error.size());
    auto finite = [&](std::size_t i) { return std::isfinite(cost[i]) && std::isfinite(error[i]); };
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < n; ++i) {
        if (!finite(i)) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < n && !dominated; ++j)
            dominated = j != i && finite(j) && cost[j] <= cost[i] && error[j] <= error[i] &&
                        (cost[j] < cost[i] || error[j] < error[i]);
        if (!dominated) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
        return cost[a] != cost[b] ? cost[a] < cost[b] : error[a] < error[b];
    });
    return front;
}

}  // namespace shadowlab

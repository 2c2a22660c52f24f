#pragma once
// The Pareto front of a cost-vs-error sweep: the points no other point beats on both (no cheaper-or-equal point
// with less-or-equal error, one of them strictly). No GL.
#include <cstddef>
#include <vector>

namespace shadowlab {

// Indices of the non-dominated points, in order of cost (then error). Points with a non-finite cost or error are
// never on the front. Equal points are both on it.
std::vector<std::size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error);

}  // namespace shadowlab

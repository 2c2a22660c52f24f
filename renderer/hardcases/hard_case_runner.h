#pragma once
// Selects, runs and reports the hard cases: `--case N` filtering, the result table (one row per sub-check: the
// measure, the figure, the document's threshold, pass / FAIL / not run), the JSON and the exit code.
// The table and JSON need no GL; running needs a current GL 4.5 context.
#include "hardcases/hard_case.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace shadowlab::hardcases {

// The cases whose numbers are in `requested` (all of `cases` when empty), in the list's order. A number no case has
// gives an error naming it and the valid range; `cases` must be sorted by number.
std::vector<const HardCase*> selectCases(const std::vector<HardCase>& cases, const std::vector<int>& requested,
                                         std::string& error);

// Runs one case, timed; a case that throws gets the exception's text as its error.
CaseResult runCase(const HardCase& c, CaseContext& context);

// Runs the selected cases in order (a case that throws gets its error), printing each case's table as it
// finishes when `progress` is given, and calling `onCase` (optional) with it and how many have finished. Case 5
// (both conventions) runs after the others: it compares their masks.
using CaseCallback = std::function<void(const CaseResult& result, std::size_t done, std::size_t total)>;
std::vector<CaseResult> runCases(const std::vector<const HardCase*>& cases, CaseContext& context,
                                 std::ostream* progress = nullptr, const CaseCallback& onCase = {});

// The table of one case / of all, fixed-width text.
void printCase(std::ostream& out, const CaseResult& result);
void printSummary(std::ostream& out, const std::vector<CaseResult>& results);

nlohmann::json resultsToJson(const std::vector<CaseResult>& results, bool quick);

// 0 when no case failed (rows that did not run do not fail), 1 otherwise.
int exitCode(const std::vector<CaseResult>& results);

}  // namespace shadowlab::hardcases

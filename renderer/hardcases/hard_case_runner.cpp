#include "hardcases/hard_case_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <ostream>

namespace shadowlab::hardcases {

std::vector<const HardCase*> selectCases(const std::vector<HardCase>& cases, const std::vector<int>& requested,
                                         std::string& error) {
    std::vector<const HardCase*> selected;
    for (const HardCase& c : cases)
        if (requested.empty() || std::find(requested.begin(), requested.end(), c.number) != requested.end())
            selected.push_back(&c);
    for (int n : requested) {
        const bool known = std::any_of(cases.begin(), cases.end(), [n](const HardCase& c) { return c.number == n; });
        if (!known) {
            error = "--case " + std::to_string(n) + ": no such case (the suite has cases " +
                    (cases.empty() ? std::string("none") : std::to_string(cases.front().number) + ".." +
                                                               std::to_string(cases.back().number)) +
                    ", see ../shared/HARD_CASES.md)";
            return {};
        }
    }
    return selected;
}

namespace {
constexpr int kReversedZCase = 5;
}  // namespace

CaseResult runCase(const HardCase& c, CaseContext& context) {
    CaseResult result;
    result.number = c.number;
    result.title = c.title;
    context.startCase(&result);
    const auto start = std::chrono::steady_clock::now();
    try {
        c.run(context, result);
    } catch (const std::exception& e) {
        result.error = e.what();
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (context.recordMasks) {
        std::vector<Verdict>& verdicts = context.verdicts[context.conventionName()][c.number];
        verdicts.clear();
        for (const CaseRow& row : result.rows) verdicts.push_back(row.verdict);
    }
    context.startCase(nullptr);
    return result;
}

namespace {

std::string cell(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

}  // namespace

std::vector<CaseResult> runCases(const std::vector<const HardCase*>& cases, CaseContext& context,
                                 std::ostream* progress, const CaseCallback& onCase) {
    std::vector<CaseResult> results(cases.size());
    const HardCase* reversed = nullptr;
    std::size_t reversedAt = 0;
    // Case 5 compares the masks of every other case in both conventions: record them on the first run.
    for (std::size_t i = 0; i < cases.size(); ++i)
        if (cases[i]->number == kReversedZCase) reversed = cases[i], reversedAt = i;
    context.recordMasks = reversed != nullptr;
    std::size_t done = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (cases[i] == reversed) continue;
        results[i] = runCase(*cases[i], context);
        if (progress) printCase(*progress, results[i]);
        if (onCase) onCase(results[i], ++done, cases.size());
    }
    if (reversed) {
        results[reversedAt] = runCase(*reversed, context);
        if (progress) printCase(*progress, results[reversedAt]);
        if (onCase) onCase(results[reversedAt], ++done, cases.size());
    }
    context.recordMasks = false;
    return results;
}

void printCase(std::ostream& out, const CaseResult& r) {
    char head[160];
    std::snprintf(head, sizeof head, "case %2d  %s  (%.1f s)", r.number, r.title.c_str(), r.seconds);
    out << head << "\n";
    if (!r.error.empty()) out << "    FAIL  error: " << r.error << "\n";
    std::size_t measured = 10, fig = 8;
    for (const CaseRow& row : r.rows) {
        measured = std::max(measured, row.measured.size());
        fig = std::max(fig, row.figure.size());
    }
    for (const CaseRow& row : r.rows)
        out << "    " << cell(verdictName(row.verdict), 8) << cell(row.measured, measured + 2) << cell(row.figure, fig + 2)
            << row.threshold << "\n";
    out.flush();
}

void printSummary(std::ostream& out, const std::vector<CaseResult>& results) {
    int failed = 0, rows = 0, notRun = 0;
    double seconds = 0.0;
    std::string failedList;
    for (const CaseResult& r : results) {
        seconds += r.seconds;
        for (const CaseRow& row : r.rows) {
            ++rows;
            notRun += row.verdict == Verdict::NotRun;
        }
        if (r.failed()) {
            ++failed;
            failedList += (failedList.empty() ? "" : ", ") + std::to_string(r.number);
        }
    }
    char line[200];
    std::snprintf(line, sizeof line, "%zu cases, %d sub-checks (%d not run), %d failed%s%s%s, %.1f s\n", results.size(),
                  rows, notRun, failed, failed ? " (" : "", failedList.c_str(), failed ? ")" : "", seconds);
    out << line;
}

nlohmann::json resultsToJson(const std::vector<CaseResult>& results, bool quick) {
    nlohmann::json cases = nlohmann::json::array();
    for (const CaseResult& r : results) {
        nlohmann::json rows = nlohmann::json::array();
        for (const CaseRow& row : r.rows)
            rows.push_back({{"measured", row.measured},
                            {"figure", row.figure},
                            {"threshold", row.threshold},
                            {"verdict", verdictName(row.verdict)}});
        nlohmann::json c = {{"case", r.number},   {"title", r.title},     {"passed", !r.failed()},
                            {"rows", rows},       {"pictures", r.pictures}, {"seconds", r.seconds}};
        if (!r.error.empty()) c["error"] = r.error;
        cases.push_back(c);
    }
    return {{"quick", quick}, {"passed", exitCode(results) == 0}, {"cases", cases}};
}

int exitCode(const std::vector<CaseResult>& results) {
    return std::any_of(results.begin(), results.end(), [](const CaseResult& r) { return r.failed(); }) ? 1 : 0;
}

}  // namespace shadowlab::hardcases

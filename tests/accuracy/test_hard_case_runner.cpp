// The hard-cases suite's runner (renderer/hardcases/hard_case_runner.h): --case selection and its refusals, the
// table, the JSON, the exit code, and running cases (one throws, case 5 runs after the others).
#include "gl_fixture.h"

#include "accuracy/accuracy_meter.h"
#include "hardcases/hard_case_runner.h"

#include <gtest/gtest.h>

#include <sstream>

namespace shadowlab::hardcases {
namespace {

std::vector<HardCase> fakeCases(std::vector<int>* order = nullptr) {
    std::vector<HardCase> cases;
    for (int n = 1; n <= 6; ++n)
        cases.push_back({n, "fake", [n, order](CaseContext&, CaseResult& r) {
                             if (order) order->push_back(n);
                             if (n == 3) throw std::runtime_error("broken scene");
                             r.check("figure of " + std::to_string(n), "1 %", "< 2 %", true);
                             if (n == 2) r.check("another", "7 %", "< 2 %", false);
                             if (n == 4) r.notRun("needs a key", "< 1", "needs lights.N.shadow.reversedZ");
                             if (n == 6) r.info("context", "12", "shown, not judged");
                         }});
    return cases;
}

TEST(HardCaseRunner, SelectsTheRequestedCasesInTheSuitesOrder) {
    const std::vector<HardCase> cases = fakeCases();
    std::string error;
    EXPECT_EQ(selectCases(cases, {}, error).size(), 6u);
    const std::vector<const HardCase*> two = selectCases(cases, {5, 2, 5}, error);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0]->number, 2);
    EXPECT_EQ(two[1]->number, 5);
    EXPECT_TRUE(error.empty());
}

TEST(HardCaseRunner, RefusesACaseTheSuiteDoesNotHave) {
    const std::vector<HardCase> cases = fakeCases();
    for (int bad : {0, 7, -3, 1000}) {
        std::string error;
        EXPECT_TRUE(selectCases(cases, {1, bad}, error).empty());
        EXPECT_NE(error.find("--case " + std::to_string(bad) + ": no such case"), std::string::npos) << error;
        EXPECT_NE(error.find("1..6"), std::string::npos) << error;
    }
    std::string error;
    EXPECT_TRUE(selectCases(hardCaseList(), {21}, error).empty());
    EXPECT_NE(error.find("1..20"), std::string::npos) << error;
}

TEST(HardCaseRunner, TheSuiteListsTheCasesOfTheDocument) {
    // Cases 1..20 in order (18-20: issue 20's cascade splits, seams and stale depth bounds).
    const std::vector<HardCase>& list = hardCaseList();
    ASSERT_EQ(list.size(), 20u);
    for (std::size_t i = 0; i < list.size(); ++i) {
        EXPECT_EQ(list[i].number, int(i + 1));
        EXPECT_TRUE(bool(list[i].run));
    }
}

CaseResult result(int number, std::vector<CaseRow> rows, std::string error = "") {
    CaseResult r;
    r.number = number;
    r.title = "title " + std::to_string(number);
    r.rows = std::move(rows);
    r.error = std::move(error);
    return r;
}

TEST(HardCaseRunner, ExitCodeFailsOnAFailingRowOrAnErrorNotOnRowsThatDidNotRun) {
    const CaseRow pass{"a", "1", "< 2", Verdict::Pass};
    const CaseRow notRun{"b", "not run (needs X)", "< 2", Verdict::NotRun};
    const CaseRow info{"c", "3", "context", Verdict::Info};
    const CaseRow failing{"d", "5", "< 2", Verdict::Fail};
    EXPECT_EQ(exitCode({result(1, {pass, notRun, info})}), 0);
    EXPECT_EQ(exitCode({result(1, {pass}), result(2, {failing})}), 1);
    EXPECT_EQ(exitCode({result(1, {pass}, "cannot load")}), 1);
    EXPECT_EQ(exitCode({}), 0);
}

TEST(HardCaseRunner, TheTableShowsEachRowsVerdictFigureAndThreshold) {
    std::ostringstream out;
    const std::vector<CaseResult> results = {
        result(1, {{"acne, worst t", "0.012 %", "< 0.1 %", Verdict::Pass},
                   {"flicker", "not run (needs the flicker measure)", "<= V changed", Verdict::NotRun}}),
        result(2, {{"leak", "3.000 %", "<= 0.1 %", Verdict::Fail}}), result(3, {}, "scene missing")};
    for (const CaseResult& r : results) printCase(out, r);
    printSummary(out, results);
    const std::string text = out.str();
    for (const char* part : {"case  1  title 1", "pass    acne, worst t", "0.012 %", "< 0.1 %", "not run flicker",
                             "not run (needs the flicker measure)", "FAIL    leak", "3.000 %", "FAIL  error: scene missing",
                             "3 cases, 3 sub-checks (1 not run), 2 failed (2, 3)"})
        EXPECT_NE(text.find(part), std::string::npos) << "missing '" << part << "' in\n" << text;
}

TEST(HardCaseRunner, JsonHoldsEveryRowAndTheVerdicts) {
    const std::vector<CaseResult> results = {result(1, {{"acne", "0.012 %", "< 0.1 %", Verdict::Pass}}),
                                             result(2, {{"leak", "3 %", "<= 0.1 %", Verdict::Fail}}, "")};
    const nlohmann::json json = resultsToJson(results, true);
    EXPECT_EQ(json["quick"], true);
    EXPECT_EQ(json["passed"], false);
    ASSERT_EQ(json["cases"].size(), 2u);
    EXPECT_EQ(json["cases"][0]["case"], 1);
    EXPECT_EQ(json["cases"][0]["passed"], true);
    EXPECT_EQ(json["cases"][0]["rows"][0]["figure"], "0.012 %");
    EXPECT_EQ(json["cases"][0]["rows"][0]["threshold"], "< 0.1 %");
    EXPECT_EQ(json["cases"][1]["rows"][0]["verdict"], "FAIL");
    EXPECT_EQ(json["cases"][1]["passed"], false);
}

class HardCaseRun : public test::GlTest {};

TEST_F(HardCaseRun, RunsEveryCaseKeepsGoingAfterOneThrowsAndRunsCaseFiveLast) {
    std::vector<int> order;
    const std::vector<HardCase> cases = fakeCases(&order);
    std::string error;
    const std::vector<const HardCase*> selected = selectCases(cases, {}, error);
    AccuracyMeter meter;
    Renderer renderer;
    const HardCaseOptions options;
    CaseContext context(options, meter, renderer);
    const std::vector<CaseResult> results = runCases(selected, context);
    ASSERT_EQ(results.size(), 6u);
    EXPECT_EQ(order, (std::vector<int>{1, 2, 3, 4, 6, 5})) << "case 5 compares the others: it runs last";
    for (std::size_t i = 0; i < results.size(); ++i) EXPECT_EQ(results[i].number, int(i + 1)) << "printed in order";
    EXPECT_EQ(results[2].error, "broken scene");
    EXPECT_TRUE(results[1].failed());
    EXPECT_FALSE(results[3].failed()) << "a row that did not run does not fail";
    EXPECT_FALSE(results[5].failed()) << "an info row does not fail";
    EXPECT_EQ(exitCode(results), 1);
}

}  // namespace
}  // namespace shadowlab::hardcases

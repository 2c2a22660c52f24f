#pragma once
// What `shadowlab check` reports of a case: the line it prints (PASS / FAIL / ERROR, each figure beside its limit)
// and the JUnit XML file CI systems read (one testcase per case: a failure naming each broken limit, an error when
// the case could not be measured, properties with every figure and the overlay's path, the line in system-out).
#include "accuracy/check_case.h"
#include "accuracy/check_limits.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::cli {

struct CheckOutcome {
    const CheckCase* check = nullptr;
    std::size_t index = 0;  // from 0, in the list
    std::vector<CheckFigure> figures;
    std::string error;    // "" unless the case could not be measured (then figures may be partial)
    std::string overlay;  // the overlay PNG written for it, or ""
    // Every light's headline numbers as "lights.0 (directional)" -> numbersToJson(...), and "whole picture".
    std::vector<std::pair<std::string, nlohmann::json>> numbers;
    std::vector<std::string> notes;  // lights not measured and why
    double seconds = 0.0;

    bool failed() const;  // a limit broken (and no error)
};

// "PASS case 1/3 \"name\" (scene, preset, 320x180): lights.0 (directional): acne 0.012 % (limit 0.100 %), ...".
std::string checkLine(const CheckOutcome& outcome, std::size_t caseCount);

// The JUnit XML document of a run: one testsuite named `suite`, one testcase per outcome.
std::string checkJunitXml(const std::string& suite, const std::vector<CheckOutcome>& outcomes, double seconds);

// `text` for an XML attribute or element: & < > " ' escaped; characters XML 1.0 cannot hold (control characters,
// bytes that are not UTF-8) become U+FFFD.
std::string xmlEscape(std::string_view text);

}  // namespace shadowlab::cli

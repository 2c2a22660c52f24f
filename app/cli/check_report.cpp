#include "cli/check_report.h"

#include <algorithm>
#include <cstdio>

namespace shadowlab::cli {

bool CheckOutcome::failed() const {
    return error.empty() && std::any_of(figures.begin(), figures.end(), [](const CheckFigure& f) { return f.broken(); });
}

namespace {

const char* verdict(const CheckOutcome& o) { return !o.error.empty() ? "ERROR" : o.failed() ? "FAIL" : "PASS"; }

std::string caseTitle(const CheckOutcome& o, std::size_t count) {
    const CheckCase& c = *o.check;
    return "case " + std::to_string(o.index + 1) + "/" + std::to_string(count) + " \"" + c.name + "\" (" + c.scene +
           ", " + (c.preset.empty() ? std::string("defaults") : c.preset) +
           (c.overrides.empty() ? std::string() : ", " + std::to_string(c.overrides.size()) + " --set") + ", " +
           std::to_string(c.width) + "x" + std::to_string(c.height) + ")";
}

// Figures grouped by subject: "lights.0 (directional): acne ..., leak ...; whole picture: ...".
std::string figuresText(const std::vector<CheckFigure>& figures, bool onlyBroken) {
    std::string text, subject;
    for (const CheckFigure& f : figures) {
        if (onlyBroken && !f.broken()) continue;
        if (f.subject != subject || text.empty()) {
            text += (text.empty() ? "" : "; ") + f.subject + ": ";
            subject = f.subject;
        } else {
            text += ", ";
        }
        text += describeFigure(f);
    }
    return text;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

void property(std::string& xml, const std::string& name, const std::string& value) {
    xml += "        <property name=\"" + xmlEscape(name) + "\" value=\"" + xmlEscape(value) + "\"/>\n";
}

}  // namespace

std::string checkLine(const CheckOutcome& o, std::size_t count) {
    std::string line = std::string(verdict(o)) + " " + caseTitle(o, count) + ": ";
    if (!o.error.empty()) return line + o.error;
    return line + figuresText(o.figures, false);
}

std::string xmlEscape(std::string_view in) {
    static const char* const kReplacement = "\xEF\xBF\xBD";  // U+FFFD
    std::string out;
    for (std::size_t i = 0; i < in.size();) {
        const unsigned char c = static_cast<unsigned char>(in[i]);
        if (c < 0x80) {
            switch (c) {
                case '&': out += "&amp;"; break;
                case '<': out += "&lt;"; break;
                case '>': out += "&gt;"; break;
                case '"': out += "&quot;"; break;
                case '\'': out += "&apos;"; break;
                default:
                    // XML 1.0 allows tab, newline and carriage return among the control characters, nothing else.
                    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') out += kReplacement;
                    else out += char(c);
            }
            ++i;
            continue;
        }
        // A well-formed UTF-8 sequence (no overlong forms, no surrogates, at most U+10FFFF) is kept as it is.
        const std::size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 0;
        bool valid = length > 0 && c <= 0xF4 && c >= 0xC2 && i + length <= in.size();
        for (std::size_t k = 1; valid && k < length; ++k)
            valid = (static_cast<unsigned char>(in[i + k]) & 0xC0) == 0x80;
        if (valid) {
            const unsigned char c1 = static_cast<unsigned char>(in[i + 1]);
            if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 >= 0xA0) || (c == 0xF0 && c1 < 0x90) ||
                (c == 0xF4 && c1 >= 0x90))
                valid = false;
            // U+FFFE and U+FFFF are not XML characters.
            if (c == 0xEF && c1 == 0xBF && static_cast<unsigned char>(in[i + 2]) >= 0xBE) valid = false;
        }
        if (valid) {
            out.append(in.substr(i, length));
            i += length;
        } else {
            out += kReplacement;
            ++i;
        }
    }
    return out;
}

std::string checkJunitXml(const std::string& suite, const std::vector<CheckOutcome>& outcomes, double seconds) {
    std::size_t failures = 0, errors = 0;
    for (const CheckOutcome& o : outcomes) {
        failures += o.failed() ? 1 : 0;
        errors += o.error.empty() ? 0 : 1;
    }
    const std::string counts = " tests=\"" + std::to_string(outcomes.size()) + "\" failures=\"" +
                               std::to_string(failures) + "\" errors=\"" + std::to_string(errors) + "\" time=\"" +
                               number(seconds) + "\"";
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites name=\"shadowlab check\"" + counts + ">\n";
    xml += "  <testsuite name=\"" + xmlEscape(suite) + "\"" + counts + " skipped=\"0\">\n";
    for (const CheckOutcome& o : outcomes) {
        const CheckCase& c = *o.check;
        xml += "    <testcase classname=\"shadowlab.check\" name=\"" + xmlEscape(c.name) + "\" time=\"" +
               number(o.seconds) + "\">\n";
        xml += "      <properties>\n";
        property(xml, "scene", c.scene);
        property(xml, "preset", c.preset);
        for (const std::string& s : c.overrides) property(xml, "set", s);
        property(xml, "width", std::to_string(c.width));
        property(xml, "height", std::to_string(c.height));
        if (!o.overlay.empty()) property(xml, "overlay", o.overlay);
        for (const CheckFigure& f : o.figures) {
            const std::string name = f.subject + " " + f.limit->figure + " (" + f.limit->unit + ")";
            property(xml, name, number(f.value));
            property(xml, name + " limit", number(f.max));
        }
        for (const auto& [subject, numbers] : o.numbers)
            for (const auto& [key, value] : numbers.items())
                if (value.is_number()) property(xml, subject + " " + key, number(value.get<double>()));
        xml += "      </properties>\n";
        if (!o.error.empty()) {
            xml += "      <error type=\"not measured\" message=\"" + xmlEscape(o.error) + "\"/>\n";
        } else if (o.failed()) {
            const std::string broken = figuresText(o.figures, true);
            xml += "      <failure type=\"limit broken\" message=\"" + xmlEscape(broken) + "\">" + xmlEscape(broken) +
                   "</failure>\n";
        }
        std::string out = checkLine(o, outcomes.size()) + "\n";
        for (const std::string& n : o.notes) out += n + "\n";
        // GitLab and Jenkins show a file named this way beside the test.
        if (!o.overlay.empty()) out += "overlay: " + o.overlay + "\n[[ATTACHMENT|" + o.overlay + "]]\n";
        xml += "      <system-out>" + xmlEscape(out) + "</system-out>\n";
        xml += "    </testcase>\n";
    }
    xml += "  </testsuite>\n</testsuites>\n";
    return xml;
}

}  // namespace shadowlab::cli

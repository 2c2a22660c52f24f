// The settings reference (`shadowlab keys --markdown`, docs/settings.md): one well-formed table row per key with the
// key table's type, default, range, unit and invalidation tags, and every schema-1 alias.
#include "settings/settings_reference.h"

#include "settings/settings_fields.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace shadowlab;

namespace {

// The table row of `pattern` ("| `filter.kernel` | ..."), or "" when there is none.
std::string rowOf(const std::string& markdown, const std::string& pattern) {
    std::istringstream lines(markdown);
    for (std::string line; std::getline(lines, line);)
        if (line.starts_with("| `" + pattern + "` |")) return line;
    return {};
}

// The cells of a table row, split at pipes that are not escaped.
std::vector<std::string> cells(const std::string& row) {
    std::vector<std::string> out;
    std::string current;
    for (std::size_t i = 1; i < row.size(); ++i) {
        if (row[i] == '|' && row[i - 1] != '\\') {
            out.push_back(current.substr(current.find_first_not_of(' ')));
            out.back().erase(out.back().find_last_not_of(' ') + 1);
            current.clear();
        } else {
            current += row[i];
        }
    }
    return out;
}

}  // namespace

TEST(SettingsReference, EveryKeyHasOneRowWithItsTableEntries) {
    const std::string markdown = settingsReferenceMarkdown();
    for (const SettingsField* f : settingsKeyListing()) {
        const std::string row = rowOf(markdown, f->pattern());
        ASSERT_FALSE(row.empty()) << f->pattern() << " has no row";
        const std::vector<std::string> c = cells(row);
        ASSERT_EQ(c.size(), 7u) << row;  // key, type, default, allowed, unit, invalidates, description
        EXPECT_NE(c[2], "``") << row;
        EXPECT_EQ(c[4], f->unit.empty() ? "-" : f->unit) << row;
        EXPECT_EQ(c[5] == "-", f->invalidates == kInvalidatesNothingElse) << row;
    }
}

TEST(SettingsReference, DefaultsRangesUnitsAndTagsComeFromTheKeyTable) {
    const std::string markdown = settingsReferenceMarkdown();
    const std::vector<std::string> kernel = cells(rowOf(markdown, "filter.kernel"));
    EXPECT_EQ(kernel[1], "integer");
    EXPECT_EQ(kernel[2], "`" + std::to_string(Settings{}.filter.kernel) + "`");
    EXPECT_EQ(kernel[3], "one of 1, 3, 5, 7, 9");
    EXPECT_EQ(kernel[5], "shader variant");

    const std::vector<std::string> cone = cells(rowOf(markdown, "lights.#.spotConeDeg"));
    EXPECT_EQ(cone[3], "[1, 170]");
    EXPECT_EQ(cone[4], "degrees");
    EXPECT_EQ(cone[5], "shadow views");

    // "|c| <= 1e6" inside a cell is escaped, so the row keeps its seven cells.
    const std::vector<std::string> direction = cells(rowOf(markdown, "lights.#.direction"));
    EXPECT_NE(direction[3].find("\\|c\\| <= 1e6"), std::string::npos) << direction[3];
}

TEST(SettingsReference, ListsEverySchema1Alias) {
    const std::string markdown = settingsReferenceMarkdown();
    const std::string text = settingsReferenceText();
    for (const SettingsField& alias : schema1Aliases()) {
        EXPECT_NE(markdown.find("| `" + alias.key + "` | `" + alias.aliasOf + "` |"), std::string::npos) << alias.key;
        EXPECT_NE(text.find(alias.key + "  = " + alias.aliasOf + "\n"), std::string::npos) << alias.key;
    }
}

#pragma once
// The settings reference, generated from the key table: what `shadowlab keys` prints and, as Markdown, the generated
// part of docs/settings.md (scripts/update-docs writes it there; the ctest docs_generated compares).
#include <string>

namespace shadowlab {

// One line per key ("key  type  default D  allowed A  [unit U]  [invalidates I]  - description"), then the schema-1
// aliases.
std::string settingsReferenceText();

// The same as Markdown: an introduction, one table per key group, the schema-1 aliases.
std::string settingsReferenceMarkdown();

}  // namespace shadowlab

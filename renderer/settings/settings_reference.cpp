#include "settings/settings_reference.h"

#include "settings/settings_fields.h"

#include <sstream>
#include <utility>
#include <vector>

namespace shadowlab {

namespace {

const char* typeName(SettingsFieldKind kind) {
    switch (kind) {
    case SettingsFieldKind::Bool: return "bool";
    case SettingsFieldKind::Int: return "integer";
    case SettingsFieldKind::Float: return "number";
    case SettingsFieldKind::Enum: return "name";
    case SettingsFieldKind::Vec3: return "vec3";
    case SettingsFieldKind::String: return "string";
    case SettingsFieldKind::StringList: return "list of strings";
    }
    return "?";
}

// The value a key has when a preset leaves it out (a new light's for a light key), as a user would type it.
std::string defaultText(const SettingsField& field) {
    const nlohmann::json value = field.get(Settings{});
    return value.is_string() ? value.get<std::string>() : describeJsonValue(value);
}

// What a change makes stale besides the main pass, from the field's Invalidates tags.
std::string invalidatesText(unsigned flags) {
    static const std::pair<unsigned, const char*> kNames[] = {{kInvalidatesShadowView, "shadow views"},
                                                              {kInvalidatesSampler, "sampler"},
                                                              {kInvalidatesVariant, "shader variant"},
                                                              {kInvalidatesCamera, "camera"}};
    std::string out;
    for (const auto& [flag, name] : kNames) {
        if (!(flags & flag)) continue;
        if (!out.empty()) out += ", ";
        out += name;
    }
    return out;
}

// A field's group as the reference heads it: "lights.#.shadow.*", "sampler.*"; "" for top-level keys.
std::string groupPattern(const SettingsField& field) {
    const std::string group(field.group());
    if (field.light >= 0) return "lights.#." + (group.empty() ? std::string() : group + ".") + "*";
    return group.empty() ? std::string() : group + ".*";
}

std::string cell(const std::string& text) {
    if (text.empty()) return "-";
    std::string out;
    for (char c : text) {
        if (c == '|') out += '\\';  // a table cell's pipe
        out += c;
    }
    return out;
}

}  // namespace

std::string settingsReferenceText() {
    std::ostringstream out;
    for (const SettingsField* field : settingsKeyListing()) {
        out << field->pattern() << "  " << typeName(field->kind) << "  default " << defaultText(*field) << "  allowed "
            << field->allowed;
        if (!field->unit.empty()) out << "  unit " << field->unit;
        if (field->invalidates) out << "  invalidates " << invalidatesText(field->invalidates);
        out << "  - " << field->description << "\n";
    }
    out << "\nSchema-1 keys, still accepted:\n";
    for (const SettingsField& alias : schema1Aliases()) out << alias.key << "  = " << alias.aliasOf << "\n";
    return out.str();
}

std::string settingsReferenceMarkdown() {
    std::ostringstream out;
    out << "Every key that presets, `--set` and the editor take, generated from the key table "
           "(`renderer/settings/settings_fields.cpp`) by `shadowlab keys --markdown`. A light's keys are listed once "
           "as `lights.#.KEY`, # = 0 .. "
        << kMaxLights - 1
        << ". **Default** is the value a key takes when a preset leaves it out (for a light key: a new light's). "
           "**Invalidates** is what a change makes stale besides the main pass, which every change redraws: the "
           "light's *shadow views* (re-rendered), the maps' *sampler*, the main pass's *shader variant* (another "
           "compiled variant), the *camera* (which views it sees).\n";

    // One table per group, in the key table's order of first appearance.
    std::vector<std::pair<std::string, std::vector<const SettingsField*>>> groups;
    for (const SettingsField* field : settingsKeyListing()) {
        const std::string pattern = groupPattern(*field);
        auto it = groups.begin();
        while (it != groups.end() && it->first != pattern) ++it;
        if (it == groups.end()) it = groups.insert(groups.end(), {pattern, {}});
        it->second.push_back(field);
    }
    for (const auto& [pattern, fields] : groups) {
        out << "\n### " << (pattern.empty() ? std::string("Top-level keys") : "`" + pattern + "`") << "\n\n";
        out << "| key | type | default | allowed | unit | invalidates | description |\n";
        out << "|---|---|---|---|---|---|---|\n";
        for (const SettingsField* f : fields) {
            out << "| `" << f->pattern() << "` | " << typeName(f->kind) << " | `" << cell(defaultText(*f)) << "` | "
                << cell(f->allowed) << " | " << cell(f->unit) << " | " << cell(invalidatesText(f->invalidates))
                << " | " << cell(f->description) << " |\n";
        }
    }

    out << "\n### Schema-1 keys, still accepted\n\n"
           "The one-light presets of schema 1 named light 0's keys without `lights.0.`; they load, and `--set` "
           "takes them, as the key they stand for.\n\n"
           "| schema-1 key | stands for |\n|---|---|\n";
    for (const SettingsField& alias : schema1Aliases())
        out << "| `" << alias.key << "` | `" << alias.aliasOf << "` |\n";
    return out.str();
}

}  // namespace shadowlab

#include "settings/preset_io.h"

#include "settings/atomic_file.h"
#include "settings/json_nesting.h"
#include "settings/regular_file.h"
#include "settings/settings_fields.h"


#include <algorithm>
#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace shadowlab {

using nlohmann::json;
using nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

const char* const kMetaKeys[] = {"schema", "schemaVersion", "name", "description", "scene"};

bool isMetaKey(const std::string& key) {
    return std::find_if(std::begin(kMetaKeys), std::end(kMetaKeys), [&](const char* m) { return key == m; }) !=
           std::end(kMetaKeys);
}

bool isGroup(std::string_view name) {
    return !name.empty() && std::any_of(settingsFields().begin(), settingsFields().end(),
                                        [&](const SettingsField& f) { return f.group() == name; });
}

// Built as ordered_json so a saved file reads in Settings order: schema first, then shadow, light, ...
ordered_json buildPreset(const Settings& settings, const std::string& name, const std::string& description,
                         const std::string& scene) {
    ordered_json out = ordered_json::object();
    out["schema"] = kPresetSchema;
    out["schemaVersion"] = kPresetSchemaVersion;
    out["name"] = name;
    out["description"] = description;
    if (!scene.empty()) out["scene"] = scene;
    for (const SettingsField& f : settingsFields()) {
        ordered_json value = f.get(settings);
        if (f.group().empty())
            out[std::string(f.name())] = std::move(value);
        else
            out[std::string(f.group())][std::string(f.name())] = std::move(value);
    }
    return out;
}

// Pretty printing with short arrays ([x, y, z]) kept on one line, which nlohmann's dump(2) does not do.
void writeJson(std::string& out, const ordered_json& v, int indent) {
    auto scalar = [](const ordered_json& s) { return s.dump(-1, ' ', false, json::error_handler_t::replace); };
    if (v.is_object() && !v.empty()) {
        out += "{\n";
        std::size_t i = 0;
        for (const auto& [key, item] : v.items()) {
            out.append(static_cast<std::size_t>(indent + 2), ' ');
            out += scalar(ordered_json(key)) + ": ";
            writeJson(out, item, indent + 2);
            out += ++i < v.size() ? ",\n" : "\n";
        }
        out.append(static_cast<std::size_t>(indent), ' ');
        out += "}";
    } else if (v.is_array() && std::none_of(v.begin(), v.end(), [](const ordered_json& e) {
                   return e.is_structured();
               })) {
        out += "[";
        for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + scalar(v[i]);
        out += "]";
    } else if (v.is_structured()) {
        out += v.dump(indent + 2, ' ', false, json::error_handler_t::replace);
    } else {
        out += scalar(v);
    }
}

// nlohmann's DOM parser, but keeping the byte position of a syntax error (an out_of_range 406 "number overflow"
// carries none in its message).
class PositionedDomParser : public nlohmann::detail::json_sax_dom_parser<json> {
public:
    explicit PositionedDomParser(json& result) : json_sax_dom_parser(result, false) {}
    template <class Exception>
    bool parse_error(std::size_t position, const std::string& /*lastToken*/, const Exception& ex) {
        failed = true;
        errorPosition = position;
        errorMessage = ex.what();
        return false;
    }
    bool failed = false;
    std::size_t errorPosition = 0;
    std::string errorMessage;
};

// "" or "line:column: invalid JSON: what".
std::string parseJson(const std::string& text, json& out) {
    PositionedDomParser handler(out);
    bool ok = json::sax_parse(text, &handler);
    if (ok && !handler.failed) return {};

    // position = characters read, so the offending character is at position - 1.
    std::size_t at = std::min(handler.errorPosition > 0 ? handler.errorPosition - 1 : 0, text.size());
    std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    std::size_t lineStart = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
    std::size_t column = lineStart == std::string::npos ? at + 1 : at - lineStart;

    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." -> "syntax error ...".
    std::string what = handler.errorMessage;
    if (auto c = what.find("column "); c != std::string::npos) {
        if (auto colon = what.find(": ", c); colon != std::string::npos) what = what.substr(colon + 2);
    } else if (auto bracket = what.find("] "); bracket != std::string::npos) {
        what = what.substr(bracket + 2);
    }
    return std::to_string(line) + ":" + std::to_string(column) + ": invalid JSON: " + what;
}

}  // namespace

nlohmann::json presetToJson(const Settings& settings, const std::string& name, const std::string& description,
                            const std::string& scene) {
    return json(buildPreset(settings, name, description, scene));
}

std::string presetToText(const Settings& settings, const std::string& name, const std::string& description,
                         const std::string& scene) {
    std::string out;
    writeJson(out, buildPreset(settings, name, description, scene), 0);
    out += "\n";
    return out;
}

PresetLoadResult presetFromJson(const nlohmann::json& preset, const Settings& base) {
    PresetLoadResult r;
    if (!preset.is_object()) {
        r.errors.push_back(std::string("a preset must be a JSON object, got ") + preset.type_name());
        return r;
    }

    // Schema first: if this is not our format, or a newer one, the fields below cannot be trusted to mean anything.
    auto schema = preset.find("schema");
    if (schema == preset.end())
        r.errors.push_back(std::string("schema: missing (allowed \"") + kPresetSchema + "\")");
    else if (!schema->is_string() || *schema != kPresetSchema)
        r.errors.push_back("schema: " + describeJsonValue(*schema) + " is not a ShadowLab preset (allowed \"" +
                           kPresetSchema + "\")");
    const std::string versionAllowed = "(allowed " + std::to_string(kPresetSchemaVersion) + ")";
    auto version = preset.find("schemaVersion");
    // 1.0 is the integer 1 written by a tool that writes every number as a float; 1.5 is not a version.
    const bool integral = version != preset.end() && version->is_number() &&
                          std::trunc(version->get<double>()) == version->get<double>();
    if (version == preset.end()) {
        r.errors.push_back("schemaVersion: missing " + versionAllowed);
    } else if (!integral) {
        r.errors.push_back("schemaVersion: expected an integer, got " + describeJsonValue(*version) + " " +
                           versionAllowed);
    } else if (version->get<double>() > kPresetSchemaVersion) {
        r.errors.push_back("schemaVersion: " + describeJsonValue(*version) +
                           " is newer than this ShadowLab understands " + versionAllowed +
                           "; update ShadowLab to load this preset");
    } else if (version->get<double>() < 1) {
        r.errors.push_back("schemaVersion: " + describeJsonValue(*version) + " is not a valid version " +
                           versionAllowed);
    }
    if (!r.errors.empty()) return r;

    for (const char* key : {"name", "description", "scene"}) {
        auto it = preset.find(key);
        if (it == preset.end()) continue;
        if (!it->is_string()) {
            r.errors.push_back(std::string(key) + ": expected a string, got " + describeJsonValue(*it));
            continue;
        }
        const std::string_view k = key;
        (k == "name" ? r.name : k == "description" ? r.description : r.scene) = it->get<std::string>();
    }

    // Everything goes into a copy; the caller sees it only if nothing at all went wrong.
    Settings settings = base;
    auto apply = [&](const SettingsField& field, const json& value) {
        if (std::string error = field.set(settings, value); !error.empty()) r.errors.push_back(std::move(error));
    };
    auto unknown = [&](const std::string& key) {
        std::string warning = "unknown key '" + describeKey(key) + "' ignored";
        if (auto close = similarSettingsKeys(key); !close.empty()) warning += " (did you mean " + close.front() + "?)";
        r.warnings.push_back(std::move(warning));
    };
    for (const auto& [key, value] : preset.items()) {
        if (isMetaKey(key)) continue;
        if (const SettingsField* field = findSettingsField(key); field && field->group().empty()) {
            apply(*field, value);
        } else if (isGroup(key)) {
            if (!value.is_object()) {
                r.errors.push_back(key + ": expected an object of " + key + ".* settings, got " +
                                   describeJsonValue(value));
                continue;
            }
            for (const auto& [member, memberValue] : value.items()) {
                std::string dotted = key + "." + member;
                if (const SettingsField* f = findSettingsField(dotted))
                    apply(*f, memberValue);
                else
                    unknown(dotted);
            }
        } else if (field) {
            // A dotted key at the top level: easy to write by hand, but presets nest them.
            r.warnings.push_back("unknown key '" + key + "' ignored (write it nested: \"" +
                                 std::string(field->group()) + "\": {\"" + std::string(field->name()) + "\": ...})");
        } else {
            unknown(key);
        }
    }
    if (r.errors.empty()) r.errors = settings.validate();  // cross-field rules (near < far, ...)
    if (r.errors.empty()) r.settings = settings;
    return r;
}

PresetLoadResult presetFromText(const std::string& text, const Settings& base) {
    PresetLoadResult r;
    // Before parsing: what follows walks the value recursively in places (messages that print it).
    if (std::string error = checkJsonNesting(text); !error.empty()) {
        r.errors.push_back(std::move(error));
        return r;
    }
    json preset;
    if (std::string error = parseJson(text, preset); !error.empty()) {
        r.errors.push_back(std::move(error));
        return r;
    }
    return presetFromJson(preset, base);
}

PresetLoadResult loadPresetFile(const std::string& path, const Settings& base) {
    PresetLoadResult r;
    std::string text;
    // A preset is a few KiB; the limit refuses a video or a log file quickly.
    if (std::string error = readRegularFile(path, kMaxPresetBytes, text); !error.empty()) {
        r.errors.push_back(std::move(error));
        return r;
    }
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
    if (isPng(bytes, text.size())) {
        std::optional<std::string> embedded = findPngText(bytes, text.size(), kPresetPngKeyword);
        if (!embedded) {
            r.errors.push_back(path + ": this PNG carries no ShadowLab preset (no '" + kPresetPngKeyword +
                               "' text chunk; only screenshots written by ShadowLab have one)");
            return r;
        }
        text = std::move(*embedded);
    }
    r = presetFromText(text, base);
    // Syntax errors start with line:column and join the path without a space (path:3:7: ...).
    for (auto& e : r.errors) e = path + (!e.empty() && std::isdigit(static_cast<unsigned char>(e[0])) ? ":" : ": ") + e;
    for (auto& w : r.warnings) w = path + ": " + w;
    return r;
}

PngText presetPngText(const Settings& settings, const std::string& scene) {
    return {{kPresetPngKeyword, presetToText(settings, "screenshot", "", scene)}};
}

std::string savePresetFile(const std::string& path, const Settings& settings, const std::string& name,
                           const std::string& description, const std::string& scene) {
    const std::string failed = "cannot save preset '" + path + "'";
    if (path.empty()) return "cannot save preset: no file name given";
    if (auto problems = settings.validate(); !problems.empty())
        return failed + ": the settings are invalid: " + problems.front();

    if (std::string error = writeFileAtomically(path, presetToText(settings, name, description, scene));
        !error.empty())
        return failed + ": " + error;
    return {};
}

}  // namespace shadowlab

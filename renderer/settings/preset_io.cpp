#include "settings/preset_io.h"

#include "settings/atomic_file.h"
#include "settings/json_text.h"
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

// Built as ordered_json so a saved file reads in Settings order: schema first, then ambient, lights, sampler, ...
ordered_json buildPreset(const Settings& settings, const std::string& name, const std::string& description,
                         const std::string& scene) {
    ordered_json out = ordered_json::object();
    out["schema"] = kPresetSchema;
    out["schemaVersion"] = kPresetSchemaVersion;
    out["name"] = name;
    out["description"] = description;
    if (!scene.empty()) out["scene"] = scene;
    auto put = [](ordered_json& object, const SettingsField& f, ordered_json value) {
        if (f.group().empty())
            object[std::string(f.name())] = std::move(value);
        else
            object[std::string(f.group())][std::string(f.name())] = std::move(value);
    };
    const auto& globals = globalSettingsFields();
    // ambient and useSceneLights first, then the lights, then the rest (sampler, filter, camera, view).
    auto global = globals.begin();
    for (; global != globals.end() && global->group().empty() && global->key != "view"; ++global)
        put(out, *global, global->get(settings));
    out["lights"] = ordered_json::array();
    for (std::size_t i = 0; i < settings.lights.size() && i < kMaxLights; ++i) {
        ordered_json light = ordered_json::object();
        for (const SettingsField& f : lightSettingsFields(i)) put(light, f, f.get(settings));
        out["lights"].push_back(std::move(light));
    }
    for (; global != globals.end(); ++global) put(out, *global, global->get(settings));
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
    } else if (v.is_array() && !v.empty()) {  // the lights: one object after another, indented like the rest
        out += "[\n";
        for (std::size_t i = 0; i < v.size(); ++i) {
            out.append(static_cast<std::size_t>(indent + 2), ' ');
            writeJson(out, v[i], indent + 2);
            out += i + 1 < v.size() ? ",\n" : "\n";
        }
        out.append(static_cast<std::size_t>(indent), ' ');
        out += "]";
    } else if (v.is_structured()) {
        out += v.dump(indent + 2, ' ', false, json::error_handler_t::replace);
    } else {
        out += scalar(v);
    }
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

namespace {

void unknownKey(PresetLoadResult& r, const std::string& key) {
    std::string warning = "unknown key '" + describeKey(key) + "' ignored";
    if (auto close = similarSettingsKeys(key); !close.empty()) warning += " (did you mean " + close.front() + "?)";
    r.warnings.push_back(std::move(warning));
}

// Is some key "<prefix>..."? ("shadow." is a group, "lights.2.projection." too.)
bool isGroupPrefix(const std::string& prefix) {
    auto under = [&](const SettingsField& f) { return f.key.starts_with(prefix); };
    auto anyUnder = [&](const std::vector<SettingsField>& fields) {
        return std::any_of(fields.begin(), fields.end(), under);
    };
    if (prefix.starts_with("lights.")) {
        const std::size_t dot = prefix.find('.', 7);
        const SettingsField* type =
            dot == std::string::npos ? nullptr : findSettingsField(prefix.substr(0, dot + 1) + "type");
        return type && anyUnder(lightSettingsFields(std::size_t(type->light)));
    }
    return anyUnder(globalSettingsFields()) || anyUnder(schema1Aliases());
}

void setField(const SettingsField& field, Settings& settings, const json& value, PresetLoadResult& r) {
    if (std::string error = field.set(settings, value); !error.empty()) r.errors.push_back(std::move(error));
}

// The members of `object` as settings under `prefix` ("" at the top, "lights.1." in a light): a member is a key
// ("view": "lit") or a group of keys ("shadow": {"depthBias": 2}).
void applyMembers(const json& object, const std::string& prefix, Settings& settings, PresetLoadResult& r) {
    for (const auto& [member, value] : object.items()) {
        if (prefix.empty() && (isMetaKey(member) || member == "lights")) continue;
        const std::string key = prefix + member;
        const SettingsField* field = findSettingsField(key);
        if (field && member.find('.') == std::string::npos) {
            setField(*field, settings, value, r);
        } else if (member.find('.') == std::string::npos && isGroupPrefix(key + ".")) {
            if (!value.is_object()) {
                r.errors.push_back(key + ": expected an object of " + key + ".* settings, got " +
                                   describeJsonValue(value));
                continue;
            }
            for (const auto& [name, memberValue] : value.items()) {
                if (const SettingsField* f = findSettingsField(key + "." + name))
                    setField(*f, settings, memberValue, r);
                else
                    unknownKey(r, key + "." + name);
            }
        } else if (field) {
            // A dotted key: easy to write by hand, but presets nest them.
            const std::size_t dot = member.find('.');
            r.warnings.push_back("unknown key '" + key + "' ignored (write it nested: \"" + member.substr(0, dot) +
                                 "\": {\"" + member.substr(dot + 1) + "\": ...})");
        } else {
            unknownKey(r, key);
        }
    }
}

void applyPresetMembers(const json& preset, Settings& settings, PresetLoadResult& r, bool schema1) {
    applyMembers(preset, "", settings, r);
    auto lights = preset.find("lights");
    if (lights == preset.end()) return;
    if (schema1) {
        unknownKey(r, "lights");
        return;
    }
    if (!lights->is_array()) {
        r.errors.push_back("lights: expected a list of lights, got " + describeJsonValue(*lights));
        return;
    }
    if (lights->size() > kMaxLights) {
        r.errors.push_back("lights: " + std::to_string(lights->size()) + " lights (allowed at most " +
                           std::to_string(kMaxLights) + ")");
        return;
    }
    // The list replaces the base's: a light keeps the base's values for keys it omits (new ones take defaults).
    settings.lights.resize(lights->size());
    for (std::size_t i = 0; i < lights->size(); ++i) {
        const json& light = (*lights)[i];
        const std::string prefix = "lights." + std::to_string(i) + ".";
        if (!light.is_object()) {
            r.errors.push_back(prefix.substr(0, prefix.size() - 1) + ": expected an object, got " +
                               describeJsonValue(light));
            continue;
        }
        applyMembers(light, prefix, settings, r);
    }
}

}  // namespace

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
    const std::string versionAllowed = "(allowed 1 to " + std::to_string(kPresetSchemaVersion) + ")";
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
    const bool schema1 = version->get<double>() < 2;
    // A schema-1 preset is a one-light scene: its keys address light 0 through the aliases.
    if (schema1) settings.lights.resize(1);
    applyPresetMembers(preset, settings, r, schema1);
    if (r.errors.empty()) r.errors = settings.validate();  // cross-field rules (near < far, ...)
    if (r.errors.empty()) r.settings = settings;
    return r;
}

PresetLoadResult presetFromText(const std::string& text, const Settings& base) {
    PresetLoadResult r;
    json preset;
    if (std::string error = parseJsonText(text, preset); !error.empty()) {
        r.errors.push_back(std::move(error));
        return r;
    }
    return presetFromJson(preset, base);
}

PresetLoadResult loadPresetFile(const std::string& path, const Settings& base) {
    PresetLoadResult r;
    std::string text;
    RegularFileReader file;
    if (std::string error = file.open(path); !error.empty()) {
        r.errors.push_back(std::move(error));
        return r;
    }
    std::uint8_t head[sizeof kPngSignature];
    if (file.size() >= sizeof head && file.readAt(0, sizeof head, head) && isPng(head, sizeof head)) {
        // A screenshot of any size: only its text chunks are read, never its pixels, so the preset limit applies to
        // the preset's text, not to the picture.
        std::string why;
        std::optional<std::string> embedded = findPngText(
            [&](std::uint64_t offset, std::size_t n, std::uint8_t* out) { return file.readAt(offset, n, out); },
            file.size(), kPresetPngKeyword, kMaxPresetBytes, &why);
        if (!embedded) {
            r.errors.push_back(path + ": " +
                               (!why.empty() ? why
                                             : std::string("this PNG carries no ShadowLab preset (no '") +
                                                   kPresetPngKeyword +
                                                   "' text chunk; only screenshots written by ShadowLab have one)"));
            return r;
        }
        text = std::move(*embedded);
    } else if (std::string error = readRegularFile(path, kMaxPresetBytes, text); !error.empty()) {
        // A preset is a few KiB; the limit refuses a video or a log file quickly.
        r.errors.push_back(std::move(error));
        return r;
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

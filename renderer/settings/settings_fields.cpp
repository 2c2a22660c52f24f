#include "settings/settings_fields.h"

#include "settings/json_nesting.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <type_traits>
#include <utility>

namespace shadowlab {

using nlohmann::json;

namespace {

// Shortest text of a double: "1e6" rather than "1e+06", "0.0001" rather than "1.0000000000000000e-04".
std::string formatNumber(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    std::string s(buf, res.ptr);
    // to_chars writes exponents as e+06 / e-04; users type 1e6 / 1e-4.
    if (auto e = s.find('e'); e != std::string::npos) {
        std::string mantissa = s.substr(0, e);
        std::string exponent = s.substr(e + 1);
        bool negative = !exponent.empty() && exponent[0] == '-';
        if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) exponent.erase(0, 1);
        exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
        s = mantissa + "e" + (negative ? "-" : "") + exponent;
    }
    return s;
}

// A float as the JSON double that prints shortest yet reads back (through double -> float) as the same float:
// 0.1f is saved as 0.1, not 0.10000000149011612. Falls back to the exact widening if the shortest decimal would
// round differently through double (never seen, but exact round trips are a promise).
json floatToJson(float f) {
    if (!std::isfinite(f)) return json(static_cast<double>(f));  // validate() reports it; dump() would write null
    char buf[32];
    auto res = std::to_chars(buf, buf + sizeof buf, f);
    double d = 0.0;
    auto back = std::from_chars(buf, res.ptr, d);
    if (back.ec != std::errc{} || static_cast<float>(d) != f) d = static_cast<double>(f);
    return json(d);
}

json componentToJson(float f) { return floatToJson(f); }
// Doubles: nlohmann writes the shortest decimal that reads back to the same double.
json componentToJson(double d) { return json(d); }

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string joined(const std::vector<std::string>& items, std::string_view sep = ", ") {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i) out += sep;
        out += items[i];
    }
    return out;
}

std::string problem(const std::string& key, const std::string& what, const std::string& allowed) {
    return key + ": " + what + " (allowed " + allowed + ")";
}

std::string rangeText(double lo, double hi) {
    // Appended piecewise: `"[" + std::string&&` trips a GCC 12 -Wrestrict false positive (PR 105329).
    std::string s = "[";
    s += formatNumber(lo);
    s += ", ";
    s += formatNumber(hi);
    s += "]";
    return s;
}

// ---- field factories. `access` is a generic lambda returning a reference into Settings (const or not). ----

SettingsField namedField(std::string fieldKey, std::string description, SettingsFieldKind kind) {
    SettingsField f;
    f.key = std::move(fieldKey);
    f.description = std::move(description);
    f.kind = kind;
    return f;
}

template <class Access>
SettingsField floatField(std::string fieldKey, std::string description, double lo, double hi, Access access) {
    SettingsField f = namedField(std::move(fieldKey), std::move(description), SettingsFieldKind::Float);
    f.min = lo;
    f.max = hi;
    f.allowed = rangeText(lo, hi);
    f.get = [access](const Settings& s) { return floatToJson(access(s)); };
    f.set = [key = f.key, allowed = f.allowed, lo, hi, access](Settings& s, const json& j) -> std::string {
        if (!j.is_number()) return problem(key, "expected a number, got " + describeJsonValue(j), allowed);
        double v = j.get<double>();
        if (!std::isfinite(v)) return problem(key, describeJsonValue(j) + " is not a finite number", allowed);
        if (v < lo || v > hi) return problem(key, describeJsonValue(j) + " is out of range", allowed);
        access(s) = static_cast<float>(v);
        return {};
    };
    return f;
}

template <class Access>
SettingsField intField(std::string fieldKey, std::string description, int lo, int hi, std::vector<int> onlyValues,
                       Access access) {
    SettingsField f = namedField(std::move(fieldKey), std::move(description), SettingsFieldKind::Int);
    f.min = lo;
    f.max = hi;
    f.intChoices = std::move(onlyValues);
    if (f.intChoices.empty()) {
        f.allowed = "integer in " + rangeText(lo, hi);
    } else {
        std::vector<std::string> names;
        for (int c : f.intChoices) names.push_back(std::to_string(c));
        f.allowed = "one of " + joined(names);
    }
    f.get = [access](const Settings& s) { return json(access(s)); };
    f.set = [key = f.key, allowed = f.allowed, lo, hi, only = f.intChoices, access](Settings& s,
                                                                                     const json& j) -> std::string {
        if (!j.is_number()) return problem(key, "expected an integer, got " + describeJsonValue(j), allowed);
        double v = j.get<double>();
        if (!std::isfinite(v)) return problem(key, describeJsonValue(j) + " is not a finite number", allowed);
        // 2048.0 is accepted (some tools write every number as a float); 2.5 is not.
        if (j.is_number_float() && std::trunc(v) != v)
            return problem(key, describeJsonValue(j) + " is not an integer", allowed);
        if (v < lo || v > hi) return problem(key, describeJsonValue(j) + " is out of range", allowed);
        int iv = static_cast<int>(v);
        if (!only.empty() && std::find(only.begin(), only.end(), iv) == only.end())
            return problem(key, describeJsonValue(j) + " is not an allowed value", allowed);
        access(s) = iv;
        return {};
    };
    return f;
}

template <class Access>
SettingsField boolField(std::string fieldKey, std::string description, Access access) {
    SettingsField f = namedField(std::move(fieldKey), std::move(description), SettingsFieldKind::Bool);
    f.min = 0;
    f.max = 1;
    f.allowed = "true or false";
    f.get = [access](const Settings& s) { return json(static_cast<bool>(access(s))); };
    f.set = [key = f.key, allowed = f.allowed, access](Settings& s, const json& j) -> std::string {
        if (!j.is_boolean()) return problem(key, "expected true or false, got " + describeJsonValue(j), allowed);
        access(s) = j.get<bool>();
        return {};
    };
    return f;
}

template <class Enum, class Access>
SettingsField enumField(std::string fieldKey, std::string description,
                        std::vector<std::pair<Enum, std::string>> names, Access access) {
    SettingsField f = namedField(std::move(fieldKey), std::move(description), SettingsFieldKind::Enum);
    for (const auto& n : names) f.choices.push_back(n.second);
    f.min = 0;
    f.max = static_cast<double>(names.size()) - 1.0;
    f.allowed = "one of " + joined(f.choices);
    f.get = [names, access](const Settings& s) {
        for (const auto& [value, name] : names)
            if (access(s) == value) return json(name);
        // A value outside the enum (memory corruption, a bad cast): set() and validate() reject this name.
        return json("<invalid " + std::to_string(static_cast<int>(access(s))) + ">");
    };
    f.set = [key = f.key, allowed = f.allowed, names, access](Settings& s, const json& j) -> std::string {
        if (!j.is_string()) return problem(key, "expected a name, got " + describeJsonValue(j), allowed);
        const auto& text = j.get_ref<const std::string&>();
        for (const auto& [value, name] : names) {
            if (text == name) {
                access(s) = value;
                return {};
            }
        }
        for (const auto& [value, name] : names)
            if (lower(text) == name)  // names are case-sensitive, but say which one was meant
                return problem(key, "unknown value " + describeJsonValue(j) + ", did you mean \"" + name + "\"?",
                               allowed);
        return problem(key, "unknown value " + describeJsonValue(j), allowed);
    };
    return f;
}

// `check` returns what is wrong with an already finite vector, or "".
template <class Access, class Check>
SettingsField vec3Field(std::string fieldKey, std::string description, std::string allowedExtra, Check check,
                        Access access) {
    SettingsField f = namedField(std::move(fieldKey), std::move(description), SettingsFieldKind::Vec3);
    f.allowed = "[x, y, z], finite" + (allowedExtra.empty() ? std::string() : ", " + allowedExtra);
    // glm::vec3 (directions, the light) or glm::dvec3 (the camera: full double precision, e.g. 1000000.001).
    f.get = [access](const Settings& s) {
        const auto& v = access(s);
        return json::array({componentToJson(v.x), componentToJson(v.y), componentToJson(v.z)});
    };
    f.set = [key = f.key, allowed = f.allowed, check, access](Settings& s, const json& j) -> std::string {
        bool shapeOk = j.is_array() && j.size() == 3;
        for (std::size_t i = 0; shapeOk && i < 3; ++i) shapeOk = j[i].is_number();
        if (!shapeOk) return problem(key, "expected [x, y, z], got " + describeJsonValue(j), allowed);
        double c[3];
        for (std::size_t i = 0; i < 3; ++i) {
            c[i] = j[i].get<double>();
            if (!std::isfinite(c[i])) return problem(key, describeJsonValue(j) + " is not finite", allowed);
        }
        if (std::string what = check(c[0], c[1], c[2]); !what.empty())
            return problem(key, describeJsonValue(j) + " " + what, allowed);
        auto& v = access(s);
        using Component = std::remove_reference_t<decltype(v.x)>;
        v = {static_cast<Component>(c[0]), static_cast<Component>(c[1]), static_cast<Component>(c[2])};
        return {};
    };
    return f;
}

// Positions: beyond 1e7 a float's step is ~1 unit and light/camera matrices fall apart (HARD_CASES 3).
auto boundedPosition(double limit) {
    return [limit](double x, double y, double z) -> std::string {
        if (std::max({std::abs(x), std::abs(y), std::abs(z)}) > limit) return "has a component beyond the limit";
        return {};
    };
}

// Directions are normalized in float: a zero vector gives NaN (HARD_CASES 14), a huge one overflows the dot product.
std::string directionCheck(double x, double y, double z) {
    if (std::max({std::abs(x), std::abs(y), std::abs(z)}) > 1e6) return "has a component beyond the limit";
    if (std::sqrt(x * x + y * y + z * z) < 1e-6) return "has (near) zero length";
    return {};
}

std::vector<SettingsField> buildFields() {
    std::vector<SettingsField> f;

    // shadow map
    f.push_back(intField("shadow.resolution",
                         "Shadow map size, texels per side (the GPU's GL_MAX_TEXTURE_SIZE may lower the limit)", 16,
                         32768, {}, [](auto& s) -> auto& { return s.shadow.resolution; }));
    f.push_back(enumField<DepthFormat>(
        "shadow.depthFormat", "Depth texture format of the shadow map",
        {{DepthFormat::D16, "d16"}, {DepthFormat::D24, "d24"}, {DepthFormat::D32F, "d32f"}},
        [](auto& s) -> auto& { return s.shadow.format; }));
    f.push_back(floatField("shadow.depthBias",
                           "DepthBias (GL polygon offset units): constant bias in steps of the depth format", -1e6,
                           1e6, [](auto& s) -> auto& { return s.shadow.depthBias; }));
    f.push_back(floatField("shadow.slopeScaledDepthBias",
                           "SlopeScaledDepthBias (GL polygon offset factor): times the polygon's max depth slope",
                           -100, 100, [](auto& s) -> auto& { return s.shadow.slopeScaledDepthBias; }));
    f.push_back(floatField("shadow.depthBiasClamp",
                           "DepthBiasClamp (GL polygon offset clamp): max bias in [0,1] depth units, 0 = no clamp",
                           0, 1, [](auto& s) -> auto& { return s.shadow.depthBiasClamp; }));
    f.push_back(floatField("shadow.normalOffset", "Lookup moved along the surface normal, in shadow-map texels", 0,
                           16, [](auto& s) -> auto& { return s.shadow.normalOffset; }));
    f.push_back(enumField<CullMode>("shadow.cullMode",
                                    "Faces culled in the shadow pass (never those of double-sided materials; back "
                                    "drops single-sided casters seen from behind, front detaches contact shadows)",
                                    {{CullMode::Back, "back"}, {CullMode::Front, "front"}, {CullMode::None, "none"}},
                                    [](auto& s) -> auto& { return s.shadow.cullMode; }));

    // light
    f.push_back(enumField<LightType>("light.type", "Light type",
                                     {{LightType::Directional, "directional"}, {LightType::Spot, "spot"}},
                                     [](auto& s) -> auto& { return s.light.type; }));
    f.push_back(vec3Field("light.direction", "Direction the light travels (need not be normalized)",
                          "|c| <= 1e6, length >= 1e-6", directionCheck,
                          [](auto& s) -> auto& { return s.light.direction; }));
    f.push_back(vec3Field("light.position", "Spot light position, world units", "|c| <= 1e7", boundedPosition(1e7),
                          [](auto& s) -> auto& { return s.light.position; }));
    f.push_back(floatField("light.spotConeDeg", "Spot light full cone angle, degrees", 1, 170,
                           [](auto& s) -> auto& { return s.light.spotConeDeg; }));
    f.push_back(floatField("light.intensity", "Light intensity (multiplies the direct term)", 0, 100,
                           [](auto& s) -> auto& { return s.light.intensity; }));
    f.push_back(floatField("light.ambient", "Ambient term, unaffected by shadows", 0, 1,
                           [](auto& s) -> auto& { return s.light.ambient; }));
    f.push_back(boolField("light.useSceneLight",
                          "Take type, direction, position and cone from the scene's first glTF light",
                          [](auto& s) -> auto& { return s.light.useSceneLight; }));

    // light projection
    f.push_back(boolField("projection.autoFit",
                          "Fit ortho size, near and far (spot: near, far) to the scene's bounding sphere",
                          [](auto& s) -> auto& { return s.projection.autoFit; }));
    f.push_back(floatField("projection.orthoSize", "Full width of the square ortho volume, world units (no autoFit)",
                           1e-3, 1e7, [](auto& s) -> auto& { return s.projection.orthoSize; }));
    f.push_back(floatField("projection.near", "Light near plane, world units (no autoFit)", 1e-4, 1e7,
                           [](auto& s) -> auto& { return s.projection.nearPlane; }));
    f.push_back(floatField("projection.far", "Light far plane, world units (no autoFit)", 1e-3, 1e8,
                           [](auto& s) -> auto& { return s.projection.farPlane; }));
    f.push_back(boolField("projection.depthClamp",
                          "GL_DEPTH_CLAMP in the shadow pass: casters before the near plane still cast",
                          [](auto& s) -> auto& { return s.projection.depthClamp; }));

    // sampler
    f.push_back(enumField<AddressMode>("sampler.addressMode", "Shadow map address mode outside [0,1]",
                                       {{AddressMode::Wrap, "wrap"},
                                        {AddressMode::ClampToEdge, "clamp"},
                                        {AddressMode::ClampToBorder, "border"}},
                                       [](auto& s) -> auto& { return s.sampler.addressMode; }));
    f.push_back(floatField("sampler.borderDepth", "Depth returned outside the map with border addressing; 1 = lit",
                           0, 1, [](auto& s) -> auto& { return s.sampler.borderDepth; }));

    // filter
    f.push_back(enumField<FilterKind>("filter.kind", "Shadow filter",
                                      {{FilterKind::Point, "point"},
                                       {FilterKind::Hardware2x2, "hardware2x2"},
                                       {FilterKind::Pcf, "pcf"},
                                       {FilterKind::Poisson, "poisson"}},
                                      [](auto& s) -> auto& { return s.filter.kind; }));
    f.push_back(intField("filter.kernel", "PCF grid size, NxN samples", 1, 9, {1, 3, 5, 7, 9},
                         [](auto& s) -> auto& { return s.filter.kernel; }));
    f.push_back(floatField("filter.poissonRadius", "Poisson disk radius, shadow-map texels", 0.5, 16,
                           [](auto& s) -> auto& { return s.filter.poissonRadius; }));

    // camera
    f.push_back(boolField("camera.autoFrame", "Place the camera to frame the scene (position/target ignored)",
                          [](auto& s) -> auto& { return s.camera.autoFrame; }));
    f.push_back(vec3Field("camera.position", "Camera position, world units", "|c| <= 1e7", boundedPosition(1e7),
                          [](auto& s) -> auto& { return s.camera.position; }));
    f.push_back(vec3Field("camera.target", "Point the camera looks at, world units", "|c| <= 1e7",
                          boundedPosition(1e7), [](auto& s) -> auto& { return s.camera.target; }));
    f.push_back(floatField("camera.fovYDeg", "Camera vertical field of view, degrees", 5, 150,
                           [](auto& s) -> auto& { return s.camera.fovYDeg; }));

    f.push_back(enumField<ViewMode>(
        "view", "What the main view shows",
        {{ViewMode::Lit, "lit"}, {ViewMode::Shadow, "shadow"}, {ViewMode::LightDepth, "light-depth"}},
        [](auto& s) -> auto& { return s.view; }));
    return f;
}

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0u : 1u)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

}  // namespace

std::string_view SettingsField::group() const {
    std::string_view k = key;
    auto dot = k.find('.');
    return dot == std::string_view::npos ? std::string_view{} : k.substr(0, dot);
}

std::string_view SettingsField::name() const {
    std::string_view k = key;
    auto dot = k.find('.');
    return dot == std::string_view::npos ? k : k.substr(dot + 1);
}

const std::vector<SettingsField>& settingsFields() {
    static const std::vector<SettingsField> fields = buildFields();
    return fields;
}

const SettingsField* findSettingsField(std::string_view key) {
    for (const auto& f : settingsFields())
        if (f.key == key) return &f;
    return nullptr;
}

std::vector<std::string> similarSettingsKeys(std::string_view key) {
    // No key is near a long string, and edit distance costs length squared: a 16 MB key would take seconds.
    if (key.size() > kMaxSuggestedKeyLength) return {};
    const std::string query = lower(key);
    const std::string_view queryName = [&] {
        std::string_view q = query;
        auto dot = q.rfind('.');
        return dot == std::string_view::npos ? q : q.substr(dot + 1);
    }();
    // Score = edit distance, case-insensitive, against the full key and against the part after the dot
    // (so "depthbias" and "shadow.depthBais" both find shadow.depthBias).
    std::vector<std::pair<std::size_t, std::string>> scored;
    for (const auto& f : settingsFields()) {
        std::size_t d = std::min(editDistance(query, lower(f.key)), editDistance(queryName, lower(f.name())));
        std::size_t limit = std::clamp<std::size_t>(f.name().size() / 3, 1, 3);
        if (d <= limit)
            scored.emplace_back(d, f.key);
        else if (queryName.size() >= 3 && lower(f.name()).find(queryName) != std::string::npos)
            scored.emplace_back(limit + 1, f.key);  // a part of the name: "shadow.bias" -> the three bias keys
    }
    std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> out;
    for (auto& s : scored) out.push_back(std::move(s.second));
    return out;
}

namespace {

constexpr std::size_t kMaxDescribedLength = 80;

// Appends a short text of `value` to `out`, stopping once `out` is longer than a message shows: deep or huge values
// cost no more than a short one, and the walk's depth is bounded (no stack overflow on "[[[[...").
void describeInto(std::string& out, const json& value, int depth) {
    if (out.size() > kMaxDescribedLength) return;
    if (value.is_number_float()) {
        out += formatNumber(value.get<double>());
    } else if (value.is_string()) {
        // Cut before quoting: a 16 MB string is not escaped whole; bytes that are not UTF-8 print as U+FFFD.
        const std::string& s = value.get_ref<const std::string&>();
        out += json(s.substr(0, kMaxDescribedLength)).dump(-1, ' ', false, json::error_handler_t::replace);
    } else if (value.is_structured()) {
        const bool array = value.is_array();
        out += array ? "[" : "{";
        if (depth >= 8 && !value.empty()) out += "...";
        else {
            bool first = true;
            for (auto it = value.begin(); it != value.end() && out.size() <= kMaxDescribedLength; ++it) {
                out += first ? "" : ", ";
                first = false;
                if (!array) out += json(it.key()).dump(-1, ' ', false, json::error_handler_t::replace) + ": ";
                describeInto(out, *it, depth + 1);
            }
        }
        out += array ? "]" : "}";
    } else {
        out += value.dump();  // null, true/false, integers
    }
}

}  // namespace

std::string describeJsonValue(const json& value) {
    std::string text;
    describeInto(text, value, 0);
    if (text.size() > kMaxDescribedLength) text = text.substr(0, kMaxDescribedLength - 3) + "...";
    return text;
}

std::string describeKey(std::string_view key) {
    constexpr std::size_t shown = 60;
    std::string text = json(std::string(key.substr(0, shown))).dump(-1, ' ', false, json::error_handler_t::replace);
    text = text.substr(1, text.size() - 2);  // the escaping without the quotes
    if (key.size() > shown) text += "... (" + std::to_string(key.size()) + " bytes)";
    return text;
}

std::string applySettingOverride(Settings& settings, std::string_view keyEqualsValue) {
    auto eq = keyEqualsValue.find('=');
    if (eq == std::string_view::npos)
        return "--set expects key=value, got '" + describeKey(keyEqualsValue) + "'";
    std::string_view key = trim(keyEqualsValue.substr(0, eq));
    std::string_view text = trim(keyEqualsValue.substr(eq + 1));

    const SettingsField* field = findSettingsField(key);
    if (!field) {
        std::vector<std::string> close = similarSettingsKeys(key);
        if (!close.empty()) return "unknown setting '" + describeKey(key) + "' (did you mean " + joined(close) + "?)";
        std::vector<std::string> all;
        for (const auto& f : settingsFields()) all.push_back(f.key);
        return "unknown setting '" + describeKey(key) + "' (valid keys: " + joined(all) + ")";
    }

    if (std::string deep = checkJsonNesting(text); !deep.empty())
        return problem(field->key, "the value " + deep.substr(deep.find("nests")), field->allowed);
    json value = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (value.is_discarded()) {
        const bool numeric = field->kind == SettingsFieldKind::Float || field->kind == SettingsFieldKind::Int;
        std::string s(text);
        char* end = nullptr;
        double number = numeric && !s.empty() ? std::strtod(s.c_str(), &end) : 0.0;
        if (numeric && !s.empty() && end == s.c_str() + s.size()) {
            // JSON has no nan/inf and refuses 1e400; strtod reads them, so the message can say what is wrong.
            if (!std::isfinite(number))
                return problem(field->key, "'" + s + "' is not a finite number", field->allowed);
            value = json(number);
        } else if (field->kind == SettingsFieldKind::Vec3) {
            // Accept "1,2,3" without brackets: shells make brackets awkward.
            value = json::parse("[" + s + "]", nullptr, false);
            if (value.is_discarded()) value = json(s);
        } else {
            value = json(s);
        }
    }
    return field->set(settings, value);
}

}  // namespace shadowlab

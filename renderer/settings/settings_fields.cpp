#include "settings/settings_fields.h"

#include "settings/json_nesting.h"
#include "shading/filters/filter_technique.h"

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

// filter.kind's names, from the technique table (one line there adds a technique).
std::vector<std::pair<FilterKind, std::string>> filterKindNames() {
    std::vector<std::pair<FilterKind, std::string>> names;
    for (const FilterTechnique* t : filterTechniques()) names.emplace_back(t->kind, t->name);
    return names;
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

// A non-empty string of at most `maxLength` bytes (an animation's name or index).
template <class Access>
SettingsField stringField(std::string fieldKey, std::string description, std::size_t maxLength, Access access) {
    SettingsField f = namedField(std::move(fieldKey), std::move(description), SettingsFieldKind::String);
    f.max = double(maxLength);
    f.allowed = "a non-empty string of at most " + std::to_string(maxLength) + " bytes";
    f.get = [access](const Settings& s) { return json(access(s)); };
    f.set = [key = f.key, allowed = f.allowed, maxLength, access](Settings& s, const json& j) -> std::string {
        // A bare number (`--set animation.play=2`) is its text: an index.
        const json text = j.is_number_integer() ? json(j.dump()) : j;
        if (!text.is_string() || text.get_ref<const std::string&>().empty() ||
            text.get_ref<const std::string&>().size() > maxLength)
            return problem(key, "expected a non-empty string, got " + describeJsonValue(j), allowed);
        access(s) = text.get<std::string>();
        return {};
    };
    return f;
}

// A list of distinct non-empty strings (node paths). A lone string is a list of one (`--set key=City/SkyBox`);
// repeats are dropped, the order kept.
template <class Access>
SettingsField stringListField(std::string fieldKey, std::string description, std::size_t maxItems,
                              std::size_t maxLength, Access access) {
    SettingsField f = namedField(std::move(fieldKey), std::move(description), SettingsFieldKind::StringList);
    f.max = double(maxItems);
    f.allowed = "a list of at most " + std::to_string(maxItems) + " non-empty strings of at most " +
                std::to_string(maxLength) + " bytes";
    f.get = [access](const Settings& s) { return json(access(s)); };
    f.set = [key = f.key, allowed = f.allowed, maxItems, maxLength, access](Settings& s, const json& j) -> std::string {
        const json list = j.is_string() ? json::array({j}) : j;
        if (!list.is_array()) return problem(key, "expected a list of strings, got " + describeJsonValue(j), allowed);
        if (list.size() > maxItems)
            return problem(key, std::to_string(list.size()) + " entries are too many", allowed);
        std::vector<std::string> items;
        for (const json& item : list) {
            if (!item.is_string() || item.get_ref<const std::string&>().empty() ||
                item.get_ref<const std::string&>().size() > maxLength)
                return problem(key, "entry " + describeJsonValue(item) + " is not a non-empty string of at most " +
                                        std::to_string(maxLength) + " bytes", allowed);
            if (std::find(items.begin(), items.end(), item.get<std::string>()) == items.end())
                items.push_back(item.get<std::string>());
        }
        access(s) = std::move(items);
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

// Manual cascade splits: all zero (the practical scheme), or increasing distances whose unused tail is zero.
std::string manualSplitsCheck(double x, double y, double z) {
    const double c[3] = {x, y, z};
    for (double v : c)
        if (v < 0.0 || v > 1e7) return "has a component outside [0, 1e7]";
    for (int i = 1; i < 3; ++i)
        if (c[i] != 0.0 && !(c[i] > c[i - 1])) return "is not increasing (each split beyond the one before it)";
    return {};
}

SettingsField tagged(SettingsField f, unsigned invalidates) {
    f.invalidates = invalidates;
    return f;
}

SettingsField inUnit(SettingsField f, std::string unit) {
    f.unit = std::move(unit);
    return f;
}

constexpr unsigned kView = kInvalidatesShadowView;
constexpr unsigned kVariant = kInvalidatesVariant;

// A light's fields. `keyOf` makes the full key from the key within the light ("shadow.depthBias", "type");
// `access` reaches the light in a Settings.
template <class KeyOf, class LightAccess>
std::vector<SettingsField> buildLightFields(KeyOf keyOf, LightAccess light) {
    std::vector<SettingsField> f;
    auto at = [light](auto member) {
        return [light, member](auto& s) -> auto& { return member(light(s)); };
    };

    f.push_back(tagged(enumField<LightType>(keyOf("type"), "Light type (a point light casts through a cube map)",
                                            {{LightType::Directional, "directional"},
                                             {LightType::Spot, "spot"},
                                             {LightType::Point, "point"}},
                                            at([](auto& l) -> auto& { return l.type; })),
                       kView | kVariant));
    f.push_back(tagged(vec3Field(keyOf("direction"), "Direction the light travels (need not be normalized; not point)",
                                 "|c| <= 1e6, length >= 1e-6", directionCheck,
                                 at([](auto& l) -> auto& { return l.direction; })),
                       kView));
    f.push_back(tagged(inUnit(vec3Field(keyOf("position"), "Spot or point light position", "|c| <= 1e7",
                                        boundedPosition(1e7), at([](auto& l) -> auto& { return l.position; })),
                              "world units"),
                       kView));
    {
        // A range is the far plane of the light's views, whose near plane is at least 1e-4: a range below 1e-3
        // leaves no depth between them, so it is refused here (naming the range), not later as "near >= far".
        constexpr double kMinRange = 1e-3;
        SettingsField range = floatField(keyOf("range"),
                                         "Spot or point light range (glTF's range): nothing beyond it is lit or "
                                         "shadowed; 0 = no limit",
                                         0, 1e7, at([](auto& l) -> auto& { return l.range; }));
        range.unit = "world units";
        range.set = [key = range.key, allowed = range.allowed, set = range.set](Settings& s, const nlohmann::json& j) {
            if (j.is_number() && j.get<double>() > 0.0 && j.get<double>() < kMinRange)
                return problem(key, describeJsonValue(j) + " is too short for a light's view (its near plane is at "
                                    "least 1e-4): 0 for no limit, else at least 0.001", allowed);
            return set(s, j);
        };
        f.push_back(tagged(std::move(range), kView));
    }
    f.push_back(tagged(inUnit(floatField(keyOf("spotConeDeg"), "Spot light full cone angle", 1, 170,
                                         at([](auto& l) -> auto& { return l.spotConeDeg; })),
                              "degrees"),
                       kView));
    f.push_back(floatField(keyOf("intensity"), "Light intensity (multiplies the direct term)", 0, 100,
                           at([](auto& l) -> auto& { return l.intensity; })));
    f.push_back(vec3Field(keyOf("color"), "Light colour, linear RGB", "each in [0, 100]",
                          [](double x, double y, double z) -> std::string {
                              if (std::min({x, y, z}) < 0 || std::max({x, y, z}) > 100)
                                  return "has a component outside [0, 100]";
                              return {};
                          },
                          at([](auto& l) -> auto& { return l.color; })));
    f.push_back(tagged(boolField(keyOf("enabled"), "The light shines (and casts, if castsShadows)",
                                 at([](auto& l) -> auto& { return l.enabled; })),
                       kView | kVariant));
    f.push_back(tagged(boolField(keyOf("castsShadows"), "The light has shadow views (off: it lights everything)",
                                 at([](auto& l) -> auto& { return l.castsShadows; })),
                       kView | kVariant));
    // Its size: only the soft reference reads it (a hard technique ignores it), so no view or variant is stale.
    f.push_back(inUnit(floatField(keyOf("size"),
                                  "Light size for the soft reference: a directional light's angular diameter "
                                  "(degrees, at most 90), a spot or point light's radius (world units); 0 = a hard "
                                  "light. glTF has no size: a preset sets it",
                                  0, 1e6, at([](auto& l) -> auto& { return l.size; })),
                       "degrees (directional) or world units (spot, point)"));

    // its shadow map
    f.push_back(tagged(inUnit(intField(keyOf("shadow.resolution"),
                                       "Shadow map size per side (the GPU's GL_MAX_TEXTURE_SIZE may lower the limit)",
                                       16, 32768, {}, at([](auto& l) -> auto& { return l.shadow.resolution; })),
                              "texels"),
                       kView | kVariant));  // lights of one size and format share a map array: the array count
    f.push_back(tagged(enumField<DepthFormat>(
                           keyOf("shadow.depthFormat"), "Depth texture format of the shadow map",
                           {{DepthFormat::D16, "d16"}, {DepthFormat::D24, "d24"}, {DepthFormat::D32F, "d32f"}},
                           at([](auto& l) -> auto& { return l.shadow.format; })),
                       kView | kVariant));
    f.push_back(tagged(inUnit(floatField(keyOf("shadow.depthBias"), "DepthBias (GL polygon offset units): constant bias",
                                         -1e6, 1e6, at([](auto& l) -> auto& { return l.shadow.depthBias; })),
                              "steps r of the depth format"),
                       kView));
    f.push_back(tagged(inUnit(floatField(keyOf("shadow.slopeScaledDepthBias"),
                                         "SlopeScaledDepthBias (GL polygon offset factor): bias that grows with the "
                                         "polygon's slope in light space",
                                         -100, 100,
                                         at([](auto& l) -> auto& { return l.shadow.slopeScaledDepthBias; })),
                              "times the polygon's max depth slope"),
                       kView));
    f.push_back(tagged(inUnit(floatField(keyOf("shadow.depthBiasClamp"),
                                         "DepthBiasClamp (GL polygon offset clamp): the largest bias, 0 = no clamp", 0,
                                         1, at([](auto& l) -> auto& { return l.shadow.depthBiasClamp; })),
                              "window depth"),
                       kView));
    f.push_back(tagged(inUnit(floatField(keyOf("shadow.normalOffset"), "Lookup moved along the surface normal", 0, 16,
                                         at([](auto& l) -> auto& { return l.shadow.normalOffset; })),
                              "shadow-map texels"),
                       kVariant));  // NORMAL_OFFSET is compiled in only when some light uses it
    f.push_back(tagged(enumField<CullMode>(keyOf("shadow.cullMode"),
                                           "Faces culled in the shadow pass (never those of double-sided materials; "
                                           "back drops single-sided casters seen from behind, front detaches contact "
                                           "shadows)",
                                           {{CullMode::Back, "back"}, {CullMode::Front, "front"}, {CullMode::None, "none"}},
                                           at([](auto& l) -> auto& { return l.shadow.cullMode; })),
                       kView));

    f.push_back(tagged(boolField(keyOf("shadow.reversedZ"),
                                 "Reversed-Z: the map stores near as 1 and far as 0 (glClipControl zero-to-one, "
                                 "cleared to 0, GEQUAL compare, polygon offset negated); the bias keys keep their "
                                 "meaning. With d32f, precision where perspective depth needs it",
                                 at([](auto& l) -> auto& { return l.shadow.reversedZ; })),
                       kView | kVariant | kInvalidatesSampler));  // maps of each convention share an array and sampler
    f.push_back(tagged(boolField(keyOf("shadow.receiverPlaneBias"),
                                 "Receiver-plane depth bias (Isidoro, GDC 2006), PCF and Poisson only: each tap compares "
                                 "the depth of the receiver's plane at the tap (from screen-space derivatives), so wide "
                                 "kernels need little slope bias. Directional and spot lights; not applied to point "
                                 "lights' cube faces (a plane does not carry across a face edge)",
                                 at([](auto& l) -> auto& { return l.shadow.receiverPlaneBias; })),
                       kVariant));  // RECEIVER_PLANE is compiled in only with a filter that takes several taps
    // When its views render again (the planner decides from these)
    f.push_back(tagged(enumField<ShadowUpdate>(keyOf("shadow.update"),
                                        "When the light's views render again: everyFrame; onChange (a key, the light "
                                        "space or a caster in the view's volume moved); cachedStatic (static casters "
                                        "rendered once into a cached depth per view, moving ones drawn over a copy of "
                                        "it within the rectangle they cover); everyNthFrame (what moved waits for the "
                                        "Nth frame: shadow.updateInterval)",
                                        {{ShadowUpdate::EveryFrame, "everyFrame"},
                                         {ShadowUpdate::OnChange, "onChange"},
                                         {ShadowUpdate::CachedStatic, "cachedStatic"},
                                         {ShadowUpdate::EveryNthFrame, "everyNthFrame"}},
                                        at([](auto& l) -> auto& { return l.shadow.update; })),
                       kView));  // its views draw once more (cachedStatic builds its cached depth)
    f.push_back(inUnit(intField(keyOf("shadow.updateInterval"),
                                "everyNthFrame's N: views moved casters dirtied render on every Nth frame only", 2,
                                60, {2, 3, 4, 6, 8, 16, 30, 60},
                                at([](auto& l) -> auto& { return l.shadow.updateInterval; })),
                       "frames"));

    // its projection
    f.push_back(tagged(boolField(keyOf("projection.autoFit"),
                                 "Fit ortho size, near and far (spot/point: near, far) to the scene's bounding sphere",
                                 at([](auto& l) -> auto& { return l.projection.autoFit; })),
                       kView));
    f.push_back(tagged(inUnit(floatField(keyOf("projection.orthoSize"),
                                         "Full width of the square ortho volume (no autoFit)", 1e-3, 1e7,
                                         at([](auto& l) -> auto& { return l.projection.orthoSize; })),
                              "world units"),
                       kView));
    f.push_back(tagged(inUnit(floatField(keyOf("projection.near"), "Light near plane (no autoFit)", 1e-4, 1e7,
                                         at([](auto& l) -> auto& { return l.projection.nearPlane; })),
                              "world units"),
                       kView));
    f.push_back(tagged(inUnit(floatField(keyOf("projection.far"), "Light far plane (no autoFit)", 1e-3, 1e8,
                                         at([](auto& l) -> auto& { return l.projection.farPlane; })),
                              "world units"),
                       kView));
    f.push_back(tagged(boolField(keyOf("projection.depthClamp"),
                                 "GL_DEPTH_CLAMP in the shadow pass: casters before the near plane still cast (directional lights; spot and point views clip at their near plane)",
                                 at([](auto& l) -> auto& { return l.projection.depthClamp; })),
                       kView));
    f.push_back(tagged(enumField<ProjectionFit>(keyOf("projection.fit"),
                                                "How a directional light's views are fitted: scene (one view around "
                                                "the whole scene) or cascades (views that follow the camera, each "
                                                "fitted to a slice of its frustum)",
                                                {{ProjectionFit::Scene, "scene"}, {ProjectionFit::Cascades, "cascades"}},
                                                at([](auto& l) -> auto& { return l.projection.fit; })),
                       kView | kVariant));  // CASCADES is compiled in only when a light has cascades
    f.push_back(tagged(intField(keyOf("projection.cascadeCount"), "Cascades of a light with fit cascades", 1, 4,
                                {1, 2, 3, 4},
                                at([](auto& l) -> auto& { return l.projection.cascadeCount; })),
                       kView | kVariant));  // the cascade block's length
    f.push_back(tagged(floatField(keyOf("projection.splitLambda"),
                                  "Practical split scheme: the blend of logarithmic (1) and uniform (0) split "
                                  "distances between the camera's near plane and the shadow distance",
                                  0, 1, at([](auto& l) -> auto& { return l.projection.splitLambda; })),
                       kView));
    f.push_back(tagged(inUnit(vec3Field(keyOf("projection.splits"),
                                        "Manual split distances from the camera, increasing: where cascade 0 ends, "
                                        "then 1, then 2 (those beyond the cascade count are ignored); [0, 0, 0] = the "
                                        "practical scheme (splitLambda) decides",
                                        "each in [0, 1e7]", manualSplitsCheck,
                                        at([](auto& l) -> auto& { return l.projection.splits; })),
                              "world units"),
                       kView));
    f.push_back(tagged(inUnit(floatField(keyOf("projection.shadowDistance"),
                                         "How far from the camera cascaded shadows reach (beyond: lit); 0 = the "
                                         "camera's far plane",
                                         0, 1e7, at([](auto& l) -> auto& { return l.projection.shadowDistance; })),
                              "world units"),
                       kView));
    f.push_back(tagged(floatField(keyOf("projection.blendBand"),
                                  "Share of each cascade's depth range where it fades into the next (0 = a hard seam)",
                                  0, 0.5, at([](auto& l) -> auto& { return l.projection.blendBand; })),
                       kView));
    f.push_back(tagged(enumField<CascadeFit>(keyOf("projection.cascadeFit"),
                                             "stable: each cascade fits its slice's bounding sphere, snapped to whole "
                                             "texels (camera motion moves no texel edge); tight: the slice's box in "
                                             "light space (more texels on screen, edges crawl as the camera moves)",
                                             {{CascadeFit::Stable, "stable"}, {CascadeFit::Tight, "tight"}},
                                             at([](auto& l) -> auto& { return l.projection.cascadeFit; })),
                       kView));
    f.push_back(tagged(enumField<DepthBounds>(keyOf("projection.depthBounds"),
                                              "Cascade splits over the depths the camera sees (SDSM): off (the "
                                              "camera's near plane to the shadow distance), sameFrame (a depth "
                                              "prepass reduced on the GPU and read back before the views are planned: "
                                              "a stall) or previousFrame (the last frame's depths: no stall, a frame "
                                              "late after a fast camera move)",
                                              {{DepthBounds::Off, "off"},
                                               {DepthBounds::SameFrame, "sameFrame"},
                                               {DepthBounds::PreviousFrame, "previousFrame"}},
                                              at([](auto& l) -> auto& { return l.projection.depthBounds; })),
                       kView));
    return f;
}

// The global fields; `ambientKey` / `sceneLightsKey` let the schema-1 aliases reuse the same definitions.
std::vector<SettingsField> buildSceneLightFields(const std::string& ambientKey, const std::string& sceneLightsKey) {
    std::vector<SettingsField> f;
    f.push_back(floatField(ambientKey, "Ambient term, unaffected by shadows", 0, 1,
                           [](auto& s) -> auto& { return s.ambient; }));
    f.push_back(tagged(boolField(sceneLightsKey,
                                 "Use the scene's glTF lights (KHR_lights_punctual, point lights included, with their "
                                 "range and intensity) instead of `lights`; each takes the shadow settings of the "
                                 "light at its index (or the last one)",
                                 [](auto& s) -> auto& { return s.useSceneLights; }),
                       kView | kVariant));
    return f;
}

std::vector<SettingsField> buildGlobalFields() {
    std::vector<SettingsField> f = buildSceneLightFields("ambient", "useSceneLights");

    // sampler
    f.push_back(tagged(enumField<AddressMode>("sampler.addressMode", "Shadow map address mode outside [0,1]",
                                              {{AddressMode::Wrap, "wrap"},
                                               {AddressMode::ClampToEdge, "clamp"},
                                               {AddressMode::ClampToBorder, "border"}},
                                              [](auto& s) -> auto& { return s.sampler.addressMode; }),
                       kInvalidatesSampler));
    f.push_back(tagged(inUnit(floatField("sampler.borderDepth",
                                         "Depth returned outside the map with border addressing; 1 = lit", 0, 1,
                                         [](auto& s) -> auto& { return s.sampler.borderDepth; }),
                              "window depth"),
                       kInvalidatesSampler));

    // filter
    f.push_back(tagged(enumField<FilterKind>("filter.kind",
                                             "Shadow filter technique: depth comparisons (point, hardware2x2, pcf, "
                                             "poisson), pcss (a blocker search, then comparisons as wide as the "
                                             "penumbra of the light's size) or filtered moments (vsm, evsm2, evsm4, "
                                             "msm: a moments pass and a blur after the shadow pass)",
                                             filterKindNames(), [](auto& s) -> auto& { return s.filter.kind; }),
                       kVariant | kInvalidatesSampler));
    f.push_back(tagged(inUnit(intField("filter.kernel", "PCF grid size: N x N taps", 1, 9, {1, 3, 5, 7, 9},
                                       [](auto& s) -> auto& { return s.filter.kernel; }),
                              "taps per side"),
                       kVariant));
    f.push_back(inUnit(floatField("filter.poissonRadius", "Poisson disk radius", 0.5, 16,
                                  [](auto& s) -> auto& { return s.filter.poissonRadius; }),
                       "shadow-map texels"));
    // the moments techniques (vsm, evsm2, evsm4, msm): storage, blur, their own terms (shading/filters/)
    f.push_back(tagged(inUnit(intField("filter.momentBits",
                                       "Moments storage precision: 16 (half float; MSM: unorm with the optimized "
                                       "quantization) or 32-bit float. EVSM's exponents are clamped to what it holds "
                                       "(5.54 at 16 bits, 42 at 32)",
                                       16, 32, {16, 32}, [](auto& s) -> auto& { return s.filter.momentBits; }),
                              "bits per moment"),
                       kInvalidatesNothingElse));
    f.push_back(inUnit(floatField("filter.blurWidth",
                                  "Moments techniques: width of the separable box blur after the moments pass (1 = "
                                  "none; fractional widths weigh the outermost taps; at most 63 texels), in "
                                  "filter.blurUnit",
                                  0, 1e4, [](auto& s) -> auto& { return s.filter.blurWidth; }),
                       "texels or world units (filter.blurUnit)"));
    f.push_back(enumField<BlurUnit>("filter.blurUnit",
                                    "Moments techniques: filter.blurWidth in each view's texels, or in world units "
                                    "(the same blur in every cascade: divided by each view's texel size)",
                                    {{BlurUnit::Texels, "texels"}, {BlurUnit::World, "world"}},
                                    [](auto& s) -> auto& { return s.filter.blurUnit; }));
    f.push_back(tagged(boolField("filter.momentMips",
                                 "Moments techniques: mip levels of the moments (each level the 2x2 mean of the "
                                 "texels below that hold a caster, built before the blur when a view's moments are), "
                                 "read trilinearly at the level of "
                                 "the pixel's footprint in the map: a distant or grazing receiver averages the texels "
                                 "it covers instead of picking one (less aliasing and flicker)",
                                 [](auto& s) -> auto& { return s.filter.momentMips; }),
                       kVariant));
    f.push_back(inUnit(floatField("filter.minVariance",
                                  "VSM / EVSM: the variance floor of Chebyshev's bound (acne on slopes against "
                                  "softer contacts; EVSM scales it by the warp's slope)",
                                  0, 0.01, [](auto& s) -> auto& { return s.filter.minVariance; }),
                       "depth units squared"));
    f.push_back(floatField("filter.bleedReduction",
                           "VSM / EVSM / MSM: light-bleeding reduction: a lit share below it becomes 0 and the rest "
                           "is rescaled (less bleeding where casters overlap, darker penumbrae)",
                           0, 0.99, [](auto& s) -> auto& { return s.filter.bleedReduction; }));
    f.push_back(floatField("filter.positiveExponent",
                           "EVSM2 / EVSM4: c+ of the warp exp(c+ (2z - 1)); above what filter.momentBits holds "
                           "(5.54 at 16, 42 at 32) it is clamped, with a warning",
                           0, 42, [](auto& s) -> auto& { return s.filter.positiveExponent; }));
    f.push_back(floatField("filter.negativeExponent",
                           "EVSM4: c- of the warp -exp(-c- (2z - 1)); clamped like filter.positiveExponent", 0, 42,
                           [](auto& s) -> auto& { return s.filter.negativeExponent; }));
    f.push_back(floatField("filter.momentBias",
                           "MSM: the moments pulled toward (0.5, 0.5, 0.5, 0.5) by this share before the Hamburger "
                           "bound (against the bound's instability; larger: more bleeding)",
                           0, 0.01, [](auto& s) -> auto& { return s.filter.momentBias; }));
    // PCSS (shading/filters/pcss_filter.cpp)
    f.push_back(inUnit(floatField("filter.blockerSearchTexels",
                                  "PCSS: the largest blocker-search radius; the search covers the map region through "
                                  "which the light (lights.#.size) reaches the receiver, clamped to this",
                                  1, 64, [](auto& s) -> auto& { return s.filter.blockerSearchTexels; }),
                       "shadow-map texels"));
    f.push_back(inUnit(floatField("filter.penumbraMaxTexels",
                                  "PCSS: the largest filter radius; the radius is half the estimated penumbra "
                                  "(receiver - blocker) / blocker x light size, clamped to [1, this]",
                                  1, 64, [](auto& s) -> auto& { return s.filter.penumbraMaxTexels; }),
                       "shadow-map texels"));

    // camera
    f.push_back(tagged(boolField("camera.autoFrame", "Place the camera to frame the scene (position/target ignored)",
                                 [](auto& s) -> auto& { return s.camera.autoFrame; }),
                       kInvalidatesCamera));
    f.push_back(tagged(inUnit(vec3Field("camera.position", "Camera position", "|c| <= 1e7", boundedPosition(1e7),
                                        [](auto& s) -> auto& { return s.camera.position; }),
                              "world units"),
                       kInvalidatesCamera));
    f.push_back(tagged(inUnit(vec3Field("camera.target", "Point the camera looks at", "|c| <= 1e7",
                                        boundedPosition(1e7), [](auto& s) -> auto& { return s.camera.target; }),
                              "world units"),
                       kInvalidatesCamera));
    f.push_back(tagged(inUnit(floatField("camera.fovYDeg", "Camera vertical field of view", 5, 150,
                                         [](auto& s) -> auto& { return s.camera.fovYDeg; }),
                              "degrees"),
                       kInvalidatesCamera));

    f.push_back(tagged(intField("camera.sceneCamera",
                                "A camera of the scene's file by its index (`render` and the editor's Scene panel "
                                "list them; the view's aspect ratio is the window's): it replaces autoFrame, position, target and fovYDeg. "
                                "-1 = the free camera",
                                -1, 1 << 20, {}, [](auto& s) -> auto& { return s.camera.sceneCamera; }),
                       kInvalidatesCamera));

    // what casts
    f.push_back(tagged(stringListField("casters.excluded",
                                       "Scene nodes whose meshes cast no shadow, by path (\"City/SkyBox\"; the "
                                       "editor's Outliner lists them): each excludes its whole subtree from the "
                                       "shadow maps and the accuracy reference. A path the scene lacks is a warning",
                                       10000, 4096, [](auto& s) -> auto& { return s.casters.excluded; }),
                       kView));
    f.push_back(tagged(stringListField("casters.static",
                                       "Scene nodes (paths, with their subtrees) forced static: a cachedStatic light "
                                       "keeps them in its cached depth even when an animation moves them (a cache "
                                       "error, warned about by node). By default what no playing animation moves is "
                                       "static",
                                       10000, 4096, [](auto& s) -> auto& { return s.casters.forcedStatic; }),
                       kView));  // the cached static depth holds other casters
    f.push_back(tagged(stringListField("casters.dynamic",
                                       "Scene nodes (paths, with their subtrees) forced dynamic: a cachedStatic light "
                                       "draws them at every update instead of caching them (casters.static wins where "
                                       "both name a node)",
                                       10000, 4096, [](auto& s) -> auto& { return s.casters.forcedDynamic; }),
                       kView));

    // animation: which clips play and when (scene/scene_animation.h poses the scene from these)
    f.push_back(tagged(stringField("animation.play",
                                   "Which of the scene file's animations play: all, none, an animation's name or its "
                                   "index in the file (the editor's Timeline lists them; a name is matched first). "
                                   "Skins and morph targets are not played",
                                   256, [](auto& s) -> auto& { return s.animation.play; }),
                       kView));
    f.push_back(inUnit(floatField("animation.time",
                                         "The time the scene is posed at: before an animation's first key or after "
                                         "its last, that key's pose holds (the editor's player loops)",
                                  0, 1e6, [](auto& s) -> auto& { return s.animation.time; }),
                       "seconds"));  // the posed scene's motion dirties the views it touches, not the key

    // the accuracy reference
    f.push_back(inUnit(intField("reference.softRays",
                                "Rays per pixel of the soft reference toward a light of size > 0 (stratified over the "
                                "light's disc; more rays, smoother penumbrae, longer measures)",
                                64, 1024, {}, [](auto& s) -> auto& { return s.reference.softRays; }),
                       "rays per pixel"));

    f.push_back(tagged(enumField<ViewMode>(
                           "view",
                           "What the main view shows: lit, the shadow factor, the first light's depth, the cascade "
                           "holding each pixel (tinted: red, green, blue, yellow from the nearest) or the first "
                           "light's shadow-map texels per screen pixel (log scale: blue < 1/4, green 1, red > 4)",
                           {{ViewMode::Lit, "lit"}, {ViewMode::Shadow, "shadow"}, {ViewMode::LightDepth, "light-depth"},
                            {ViewMode::Cascades, "cascades"}, {ViewMode::TexelDensity, "texel-density"}},
                           [](auto& s) -> auto& { return s.view; }),
                       kVariant));
    return f;
}

// Wraps a field of light `index` so that a missing light reads as null and setting light lights.size() appends one.
SettingsField boundToLight(SettingsField f, std::size_t index) {
    f.light = static_cast<int>(index);
    f.get = [index, get = f.get](const Settings& s) { return index < s.lights.size() ? get(s) : json(); };
    f.set = [index, key = f.key, set = f.set](Settings& s, const json& j) -> std::string {
        const std::size_t count = s.lights.size();
        if (index > count || index >= kMaxLights) {
            std::string what = key + ": there is no light " + std::to_string(index) + " (the settings have " +
                               std::to_string(count) + " light" + (count == 1 ? "" : "s");
            if (count < kMaxLights) what += "; lights." + std::to_string(count) + ".* adds one";
            return what + ", at most " + std::to_string(kMaxLights) + ")";
        }
        const bool appended = index == count;
        if (appended) s.lights.emplace_back();
        std::string error = set(s, j);
        if (!error.empty() && appended) s.lights.pop_back();
        return error;
    };
    return f;
}

std::vector<std::vector<SettingsField>> buildAllLightFields() {
    std::vector<std::vector<SettingsField>> all;
    for (std::size_t i = 0; i < kMaxLights; ++i) {
        const std::string prefix = "lights." + std::to_string(i) + ".";
        // The access is only reached through boundToLight's check, so the index exists there.
        std::vector<SettingsField> fields =
            buildLightFields([&](const char* rel) { return prefix + rel; },
                             [i](auto& s) -> auto& { return s.lights[i]; });
        for (SettingsField& f : fields) f = boundToLight(std::move(f), i);
        all.push_back(std::move(fields));
    }
    return all;
}

std::vector<SettingsField> buildSchema1Aliases() {
    // Schema 1 had one light: its light-level keys were "light.*", its shadow and projection groups top-level.
    std::vector<SettingsField> aliases = buildLightFields(
        [](const char* rel) {
            const std::string_view r = rel;
            return (r.starts_with("shadow.") || r.starts_with("projection.")) ? std::string(r) : "light." + std::string(r);
        },
        [](auto& s) -> auto& { return s.lights[0]; });
    for (SettingsField& f : aliases) {
        const std::string_view rel = f.key.starts_with("light.") ? std::string_view(f.key).substr(6) : f.key;
        f = boundToLight(std::move(f), 0);
        f.aliasOf = "lights.0." + std::string(rel);
    }
    // "light.range", "light.color", ... never existed in schema 1, but as aliases of light 0 they do no harm and keep
    // `--set light.X` uniform. The two light-group keys that became global:
    for (SettingsField& f : buildSceneLightFields("light.ambient", "light.useSceneLight")) {
        f.aliasOf = f.key == "light.ambient" ? "ambient" : "useSceneLights";
        aliases.push_back(std::move(f));
    }
    return aliases;
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

std::string_view SettingsField::lightKey() const {
    std::string_view k = key;
    if (light >= 0 && aliasOf.empty()) {  // "lights.<n>.<rest>"
        k.remove_prefix(k.find('.', 7) + 1);
    } else if (!aliasOf.empty() && k.starts_with("light.") && light >= 0) {
        k.remove_prefix(6);
    }
    return k;
}

std::string_view SettingsField::group() const {
    std::string_view k = lightKey();
    auto dot = k.find('.');
    return dot == std::string_view::npos ? std::string_view{} : k.substr(0, dot);
}

std::string_view SettingsField::name() const {
    std::string_view k = lightKey();
    auto dot = k.find('.');
    return dot == std::string_view::npos ? k : k.substr(dot + 1);
}

std::string SettingsField::pattern() const {
    return light >= 0 && aliasOf.empty() ? "lights.#." + std::string(lightKey()) : key;
}

const std::vector<SettingsField>& globalSettingsFields() {
    static const std::vector<SettingsField> fields = buildGlobalFields();
    return fields;
}

const std::vector<SettingsField>& lightSettingsFields(std::size_t light) {
    static const std::vector<std::vector<SettingsField>> fields = buildAllLightFields();
    return fields.at(light);
}

const std::vector<SettingsField>& schema1Aliases() {
    static const std::vector<SettingsField> aliases = buildSchema1Aliases();
    return aliases;
}

std::vector<const SettingsField*> settingsFieldsOf(const Settings& settings) {
    std::vector<const SettingsField*> out;
    for (const SettingsField& f : globalSettingsFields()) out.push_back(&f);
    for (std::size_t i = 0; i < settings.lights.size() && i < kMaxLights; ++i)
        for (const SettingsField& f : lightSettingsFields(i)) out.push_back(&f);
    return out;
}

std::vector<const SettingsField*> settingsKeyListing() {
    std::vector<const SettingsField*> out;
    for (const SettingsField& f : globalSettingsFields()) out.push_back(&f);
    for (const SettingsField& f : lightSettingsFields(0)) out.push_back(&f);
    return out;
}

const SettingsField* findSettingsField(std::string_view key) {
    if (key.starts_with("lights.")) {
        // "lights.<n>.<rest>": n in decimal without leading zeros (one spelling per key).
        std::string_view rest = key.substr(7);
        std::size_t index = 0;
        auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), index);
        const std::size_t digits = static_cast<std::size_t>(end - rest.data());
        if (ec != std::errc{} || digits == 0 || (digits > 1 && rest[0] == '0') || index >= kMaxLights ||
            digits >= rest.size() || rest[digits] != '.')
            return nullptr;
        for (const SettingsField& f : lightSettingsFields(index))
            if (f.key == key) return &f;
        return nullptr;
    }
    for (const SettingsField& f : globalSettingsFields())
        if (f.key == key) return &f;
    for (const SettingsField& f : schema1Aliases())
        if (f.key == key) return &f;
    return nullptr;
}

namespace {

bool carries(const SettingsField& f, unsigned tags) { return tags == kEveryField || (f.invalidates & tags) != 0; }

}  // namespace

SettingsDiff diffGlobals(const Settings& a, const Settings& b, unsigned tags) {
    SettingsDiff diff;
    for (const SettingsField& f : globalSettingsFields()) {
        if (carries(f, tags) && f.get(a) != f.get(b)) {
            diff.keys.push_back(f.key);
            diff.invalidates |= f.invalidates;
        }
    }
    return diff;
}

SettingsDiff diffSettings(const Settings& a, const Settings& b, unsigned tags) {
    SettingsDiff diff = diffGlobals(a, b, tags);
    const std::size_t lights = std::max(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < lights && i < kMaxLights; ++i) {
        if (i >= a.lights.size() || i >= b.lights.size()) {
            diff.keys.push_back("lights." + std::to_string(i));
            diff.invalidates |= kInvalidatesShadowView | kInvalidatesVariant;
            continue;
        }
        for (const SettingsField& f : lightSettingsFields(i)) {
            if (carries(f, tags) && f.get(a) != f.get(b)) {
                diff.keys.push_back(f.key);
                diff.invalidates |= f.invalidates;
            }
        }
    }
    return diff;
}

SettingsDiff diffLight(const LightSettings& a, const LightSettings& b, unsigned tags) {
    SettingsDiff diff;
    if (a == b) return diff;  // the common case, without a JSON value per field
    Settings sa, sb;
    sa.lights = {a};
    sb.lights = {b};
    for (const SettingsField& f : lightSettingsFields(0)) {
        if (carries(f, tags) && f.get(sa) != f.get(sb)) {
            diff.keys.emplace_back(f.lightKey());
            diff.invalidates |= f.invalidates;
        }
    }
    return diff;
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
    // Candidates: the global keys, light 0's keys (or the light the query names) and the schema-1 aliases.
    std::size_t light = 0;
    if (query.starts_with("lights.")) {
        std::from_chars(query.data() + 7, query.data() + query.size(), light);
        light = std::min(light, kMaxLights - 1);
    }
    std::vector<const SettingsField*> candidates;
    for (const SettingsField& f : globalSettingsFields()) candidates.push_back(&f);
    if (query.starts_with("lights."))
        for (const SettingsField& f : lightSettingsFields(light)) candidates.push_back(&f);
    else
        for (const SettingsField& f : schema1Aliases()) candidates.push_back(&f);
    for (const SettingsField* candidate : candidates) {
        const SettingsField& f = *candidate;
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
        for (const SettingsField* f : settingsKeyListing()) all.push_back(f->pattern());
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

std::string lightTypeName(LightType type) {
    Settings s;
    s.lights[0].type = type;
    return findSettingsField("lights.0.type")->get(s).get<std::string>();
}

}  // namespace shadowlab

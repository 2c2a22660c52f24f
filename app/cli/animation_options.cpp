#include "cli/animation_options.h"

#include "settings/settings_fields.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>

namespace shadowlab::cli {

void addAnimationOptions(CLI::App& command, std::vector<std::string>& overrides) {
    struct Given {
        std::optional<double> time;
        std::optional<std::string> animation;
    };
    auto given = std::make_shared<Given>();
    const SettingsField& time = *findSettingsField("animation.time");
    command.add_option("--time", given->time, "pose the scene's animations at this time (animation.time: " +
                                                   time.allowed + " " + time.unit + ")")
        ->check(CLI::Range(time.min, time.max).description(""))
        ->type_name("SECONDS");
    command.add_option("--animation", given->animation,
                       "which animation plays (animation.play): its name or index, all (the default) or none")
        ->type_name("NAME|INDEX");
    command.final_callback([given, &overrides] {
        // As JSON: the time exactly as typed in double, the name as a string whatever it looks like ("true", "2").
        if (given->time) overrides.push_back("animation.time=" + nlohmann::json(*given->time).dump());
        if (given->animation) overrides.push_back("animation.play=" + nlohmann::json(*given->animation).dump());
    });
}

}  // namespace shadowlab::cli

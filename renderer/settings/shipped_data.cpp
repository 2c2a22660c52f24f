#include "settings/shipped_data.h"

#include <system_error>

#ifndef SHADOWLAB_DATA_FROM_BIN
#error "SHADOWLAB_DATA_FROM_BIN (the shipped data folder relative to the binary's) is set by renderer/CMakeLists.txt"
#endif

namespace shadowlab {

namespace fs = std::filesystem;

ShippedData findShippedData(const fs::path& executable) {
    ShippedData found;
    found.tried = (executable.parent_path() / SHADOWLAB_DATA_FROM_BIN).lexically_normal();
    std::error_code ec;
    // The presets folder marks the data folder: it is what every install and build tree has.
    if (fs::is_directory(found.tried / "presets", ec)) {
        found.dir = found.tried;
        return found;
    }
    found.problem = "no shipped data: " + (found.tried / "presets").string() + " does not exist (the binary " +
                    executable.string() + " looks in " + SHADOWLAB_DATA_FROM_BIN +
                    " from its folder; run an installed bin/shadowlab (cmake --install BUILD --prefix P) or the build "
                    "tree's app/shadowlab)";
    return found;
}

const ShippedData& shippedData() {
    static const ShippedData data = [] {
        std::error_code ec;
        const fs::path self = fs::read_symlink("/proc/self/exe", ec);
        if (ec) {
            ShippedData none;
            none.problem = "no shipped data: cannot tell where this binary is (/proc/self/exe: " +
                           ec.message() + ")";
            return none;
        }
        return findShippedData(self);
    }();
    return data;
}

fs::path shippedPresetsDir() {
    const ShippedData& data = shippedData();
    return data.dir.empty() ? fs::path() : data.dir / "presets";
}

}  // namespace shadowlab

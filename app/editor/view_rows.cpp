#include "editor/view_rows.h"

#include <cstdio>

namespace shadowlab::editor {

std::string memoryText(std::size_t bytes) {
    char text[32];
    if (bytes < (std::size_t(1) << 20))
        std::snprintf(text, sizeof text, "%zu KiB", (bytes + 1023) / 1024);
    else
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1u << 20));
    return text;
}

std::vector<ViewRow> viewRows(const FrameStats& stats, const std::map<ShadowViewId, double>& lastMilliseconds) {
    std::vector<ViewRow> rows;
    for (const ShadowViewStats& v : stats.views) {
        ViewRow row;
        row.name = v.name;
        row.cascade = v.hasView && v.kind == ShadowViewKind::Cascade ? v.index : -1;
        row.ran = v.ran;
        row.update = v.hasView ? v.cache : "-";
        row.memory = v.hasView ? memoryText(v.memoryBytes) : "-";
        std::optional<double> ms = v.ran ? v.milliseconds : std::nullopt;
        if (!ms && v.hasView) {
            const auto last = lastMilliseconds.find({v.light, v.kind, v.index});
            if (last != lastMilliseconds.end()) {
                ms = last->second;
                row.timeFromEarlier = true;
            }
        }
        char text[32] = "-";
        if (ms) std::snprintf(text, sizeof text, "%.2f", *ms);
        row.milliseconds = text;
        row.why = v.reason;
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace shadowlab::editor

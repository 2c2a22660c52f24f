#pragma once
// `shadowlab measure`: how wrong one view's shadows are against the exact reference (acne %, leak %, edge error,
// the counts behind them, the cause of every mismatched pixel, what the reference cost), optionally as JSON and as
// overlay PNGs (by error, by cause). Every shadow-casting light is measured alone, then the whole picture
// (renderer/accuracy/light_accuracy.h); --light N measures only light N. With --motion, flicker instead
// (measure_motion.h).
#include <string>
#include <vector>

namespace shadowlab::cli {

struct MeasureOptions {
    std::string scene = "builtin:textbook";
    std::string preset;
    std::vector<std::string> overrides;
    int width = 1280;
    int height = 720;
    std::string json;     // optional
    std::string overlay;       // optional PNG: red acne, blue leak, yellow true boundary
    std::string causeOverlay;  // optional PNG: every mismatched pixel in its cause's colour
    std::string softOverlay;   // optional PNG: one light with a size: bleeding and over-darkening against the soft V
    int light = -1;            // --light N: only light N (index into the effective lights); -1 = every casting one
    int remeasureBench = 0;    // > 0: time that many live re-measures after a bias change (remeasure_bench.h)
    // Flicker (measure_motion.h): empty motion = an ordinary measurement; the others need --motion.
    std::string motion;        // "camera" or "light"
    int frames = -1;           // -1: not given (10)
    std::string step;          // as typed: parsed by measure_motion so "nan" or "1e999" get a clear message
    std::string direction;     // "x,y,z": camera's direction of travel / light's rotation axis
    std::string framesOut;     // folder: the worst pair's two frames as PNG
    std::string staleBounds;   // degrees as typed: the frame after a camera turn with 0 and 1 frame of depth bounds
};

// Exit code 0 unless it failed (bad input, no GL, a file that cannot be written).
int runMeasure(const MeasureOptions& options);

}  // namespace shadowlab::cli

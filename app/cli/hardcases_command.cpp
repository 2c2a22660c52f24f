#include "cli/hardcases_command.h"

#include "accuracy/accuracy_meter.h"
#include "cli/command_input.h"
#include "cli/progress.h"
#include "context/headless_context.h"
#include "frame/renderer.h"
#include "hardcases/hard_case_runner.h"
#include "settings/atomic_file.h"
#include "settings/shipped_data.h"

#include <filesystem>
#include <iostream>

namespace shadowlab::cli {

int runHardCases(const HardCasesOptions& options) {
    std::string error;
    const std::vector<const hardcases::HardCase*> selected =
        hardcases::selectCases(hardcases::hardCaseList(), options.cases, error);
    if (!error.empty()) {
        fail(error);
        return 2;
    }
    if (!options.outDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(options.outDir, ec);
        if (!std::filesystem::is_directory(options.outDir))
            return fail("--out-dir " + options.outDir + ": cannot create the folder" +
                        (ec ? " (" + ec.message() + ")" : ""));
    }
    // A scenes folder the user named must exist: a typo would otherwise turn every check into "not run", exit 0.
    if (!options.sharedScenes.empty() && !std::filesystem::is_directory(options.sharedScenes))
        return fail("--scenes " + options.sharedScenes + ": no such folder (the glTF scenes of ../shared/scenes)");
    // After --out-dir, which may be the JSON's folder.
    if (std::string e = checkOutputFolder(options.json, "--json"); !e.empty()) return fail(e);
    hardcases::HardCaseOptions caseOptions;
    caseOptions.quick = options.quick;
    caseOptions.outDir = options.outDir;
    caseOptions.sharedScenes = options.sharedScenes;
    if (caseOptions.sharedScenes.empty()) {
        // A build tree links its data folder's shared-scenes to ../shared/scenes; an install has none (test data).
        caseOptions.sharedScenes = (shippedData().tried / "shared-scenes").string();
        if (!std::filesystem::is_directory(caseOptions.sharedScenes))
            std::cerr << "note: no test scenes at " << caseOptions.sharedScenes
                      << " (only a build tree links them): the cases that need them are not run; --scenes DIR names "
                         "the ../shared/scenes folder\n";
    }
    try {
        HeadlessContext context;
        AccuracyMeter meter;
        Renderer renderer;
        hardcases::CaseContext caseContext(caseOptions, meter, renderer);
        std::cout << "hard cases of ../shared/HARD_CASES.md" << (options.quick ? " (--quick: small maps and views)" : "")
                  << " on " << renderer.glInfo().renderer << "\n";
        ProgressLine progress("hardcases", selected.size(), "cases");
        const std::vector<hardcases::CaseResult> results = hardcases::runCases(
            selected, caseContext, nullptr, [&](const hardcases::CaseResult& result, std::size_t done, std::size_t) {
                progress.setDone(done);
                progress.above([&] { hardcases::printCase(std::cout, result); });
            });
        progress.finish();
        hardcases::printSummary(std::cout, results);
        if (!options.json.empty()) {
            const std::string text = hardcases::resultsToJson(results, options.quick).dump(2) + "\n";
            if (std::string e = writeFileAtomically(options.json, text); !e.empty()) return fail(e);
            std::cout << "wrote " << options.json << "\n";
        }
        if (!options.outDir.empty()) std::cout << "pictures in " << options.outDir << "\n";
        return hardcases::exitCode(results);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}

}  // namespace shadowlab::cli

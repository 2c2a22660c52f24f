#include "cli/export_command.h"

#include "cli/command_input.h"
#include "cli/settings_from_cli.h"
#include "export/export_snippets.h"
#include "frame/camera.h"
#include "views/shadow_view.h"
#include "settings/atomic_file.h"

#include <iostream>

namespace shadowlab::cli {

int runExport(const ExportOptions& options) {
    const std::optional<ExportFormat> format = parseExportFormat(options.format);
    if (!format) {
        std::cerr << "error: --format: '" << options.format << "' is not one of " << exportFormatChoices() << "\n";
        return 2;
    }
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (std::string error = checkOutputFolder(options.out, "--out"); !error.empty()) return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings});
    if (!loaded.scene) return fail(loaded.error);

    if (options.light < -1) {
        std::cerr << "error: --light " << options.light << ": must be a light index (0 or more)\n";
        return 2;
    }
    std::optional<std::size_t> only;
    if (options.light >= 0) only = std::size_t(options.light);
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    std::string error;
    // The camera a cascaded light's cascades follow: the preset's, as render and measure see it at this size.
    const Camera camera = cameraFor(settings->camera, *loaded.scene, double(options.width) / options.height);
    const ViewCamera viewCamera = viewCameraOf(camera, double(options.width) / options.height,
                                               renderOriginOf(loaded.scene->bounds));
    const std::optional<ShadowExportSet> values =
        exportForScene(*settings, *loaded.scene, options.scene, only, error, &viewCamera, options.view);
    if (!values) {
        if (error.rfind("--light", 0) == 0 || error.rfind("--view", 0) == 0) {
            std::cerr << "error: " << error << "\n";
            return 2;
        }
        return fail(error);
    }
    const std::string text = exportSnippet(*values, *format);
    if (options.out.empty()) {
        std::cout << text;
        return 0;
    }
    if (error = writeFileAtomically(options.out, text); !error.empty()) return fail(error);
    std::size_t casting = 0;
    for (const LightExport& l : values->lights) casting += l.shadow ? 1 : 0;
    std::cout << "wrote " << options.out << " (" << options.format << ", " << values->lights.size() << " of "
              << values->lightCount << " light" << (values->lightCount == 1 ? "" : "s") << ", " << casting
              << " casting; normal offset and light volumes for " << options.scene << ")\n";
    return 0;
}

}  // namespace shadowlab::cli

#include "cli/export_command.h"

#include "cli/command_input.h"
#include "cli/settings_from_cli.h"
#include "export/export_snippets.h"
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
    SceneLoadResult loaded = loadSceneForCommand(options.scene);
    if (!loaded.scene) return fail(loaded.error);

    std::string error;
    const std::optional<ShadowExport> values = exportForScene(*settings, *loaded.scene, options.scene, error);
    if (!values) return fail(error);
    const std::string text = exportSnippet(*values, *format);
    if (options.out.empty()) {
        std::cout << text;
        return 0;
    }
    if (error = writeFileAtomically(options.out, text); !error.empty()) return fail(error);
    std::cout << "wrote " << options.out << " (" << options.format << ", normal offset and light volume for "
              << options.scene << ")\n";
    return 0;
}

}  // namespace shadowlab::cli

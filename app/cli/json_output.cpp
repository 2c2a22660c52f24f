#include "cli/json_output.h"

#include "settings/atomic_file.h"

#include <iostream>

namespace shadowlab::cli {

std::string writeJsonOutput(const std::string& path, const nlohmann::json& doc) {
    if (std::string error = writeFileAtomically(path, doc.dump(2) + "\n"); !error.empty()) return error;
    std::cout << "wrote " << path << "\n";
    return "";
}

}  // namespace shadowlab::cli

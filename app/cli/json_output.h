#pragma once
// A command's --json file: the document indented, written atomically, and "wrote PATH" on stdout.
#include <nlohmann/json.hpp>

#include <string>

namespace shadowlab::cli {

// "" on success (after printing "wrote PATH"), else why the file could not be written.
std::string writeJsonOutput(const std::string& path, const nlohmann::json& doc);

}  // namespace shadowlab::cli

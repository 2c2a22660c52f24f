#include "gl/shader_text.h"

#include "gl/shader_sources.h"

#include <algorithm>
#include <stdexcept>

namespace shadowlab::gl {

namespace {

const std::string& embeddedSource(const std::string& file) {
    const auto& sources = embeddedShaderSources();
    const auto it = sources.find(file);
    if (it == sources.end()) throw std::runtime_error("shader source not embedded: " + file);
    return it->second;
}

// `text` with each `#include "name"` line replaced by the embedded file (recursively, each file once), preceded by
// "#line 1 K" (K: the file's number in `files`) and followed by a #line back to the includer's next line. A name in
// `aliases` stands for the file it maps to (the variant chooses it); an alias the variant does not map becomes an
// #error line, which stops the compile only where the preprocessor reaches it.
std::string expandIncludes(const std::string& text, int number, std::vector<std::string>& files,
                           const IncludeAliases& aliases) {
    std::string out;
    std::size_t lineNumber = 0, begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(begin, end - begin);
        ++lineNumber;
        begin = end + 1;
        if (line.rfind("#include", 0) != 0) {
            out += line + "\n";
            continue;
        }
        const std::size_t open = line.find('"'), close = line.rfind('"');
        if (open == std::string::npos || close <= open)
            throw std::runtime_error("shader " + files[std::size_t(number)] + " line " + std::to_string(lineNumber) +
                                     ": #include needs a \"file\" name");
        std::string name = line.substr(open + 1, close - open - 1);
        if (name.rfind("alias:", 0) == 0) {
            const auto alias = aliases.find(name);
            if (alias == aliases.end()) {
                out += "#error this variant chooses no file for #include \"" + name + "\"\n";
                continue;
            }
            name = alias->second;
        }
        if (std::find(files.begin(), files.end(), name) == files.end()) {
            files.push_back(name);
            const int included = int(files.size()) - 1;
            out += "#line 1 " + std::to_string(included) + "\n";
            out += expandIncludes(embeddedSource(name), included, files, aliases);
        }
        out += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(number) + "\n";
    }
    return out;
}

std::string preprocess(const std::string& file, const std::vector<std::string>& defines, const std::string& source,
                       std::vector<std::string>& files, const IncludeAliases& aliases) {
    // Keep "#version" first: defines go right after its line.
    std::size_t versionEnd = 0;
    if (source.rfind("#version", 0) == 0) versionEnd = source.find('\n') + 1;
    std::string out = source.substr(0, versionEnd);
    for (const std::string& d : defines) out += "#define " + d + "\n";
    out += "#line 2 0\n";
    files = {file};
    out += expandIncludes(source.substr(versionEnd), 0, files, aliases);
    return out;
}


}  // namespace

std::string preprocessedSource(const std::string& file, const std::vector<std::string>& defines,
                               const std::string& text, const IncludeAliases& aliases, std::vector<std::string>& files) {
    return preprocess(file, defines, text.empty() ? embeddedSource(file) : text, files, aliases);
}

std::string preprocessedSource(const std::string& file, const std::vector<std::string>& defines,
                               const std::string& text, const IncludeAliases& aliases) {
    std::vector<std::string> files;
    return preprocessedSource(file, defines, text, aliases, files);
}

std::string sourceLegend(const std::vector<std::string>& files) {
    std::string legend;
    for (std::size_t i = 0; i < files.size(); ++i)
        legend += (i ? ", " : "(sources: ") + std::to_string(i) + " = " + files[i];
    return legend + ")";
}

}  // namespace shadowlab::gl

#pragma once
// The skeleton every rmfx XML front end shares (workspaces, replay manifests, RenderMonkey files,
// the bench's variant manifests): read the file, parse the XML (a malformed file is one error at
// its line), check the root element, let the front end read the root into a value while it
// collects diagnostics, and return the value with its warnings, or the diagnostics when one is an
// error.

#include <filesystem>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include <tinyxml2.h>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "io/xml/XmlElementReader.h"

namespace rmfx::xml {

// The value when the diagnostics hold no error (they are its warnings), else the failure.
template <class T>
Result<T> resultOf(T value, Diagnostics diagnostics) {
    if (hasErrors(diagnostics)) return Result<T>::failure(std::move(diagnostics));
    return Result<T>(std::move(value), std::move(diagnostics));
}

// Parses XML text named `file` in diagnostics. When it is well-formed with root <rootName>,
// `readRoot(root, diagnostics)` returns the value read from the root, adding what it finds to
// the diagnostics (which already hold an element after the root, if there is one).
template <class ReadRoot, class T = std::invoke_result_t<ReadRoot, const XMLElement*, Diagnostics&>>
Result<T> parseXmlText(const std::string& text, const std::string& file, const char* rootName, ReadRoot&& readRoot) {
    Diagnostics diagnostics;
    tinyxml2::XMLDocument doc;
    const XMLElement* root = parseDocument(doc, text, file, rootName, diagnostics);
    if (!root) return Result<T>::failure(std::move(diagnostics));
    T value = readRoot(root, diagnostics);
    return resultOf(std::move(value), std::move(diagnostics));
}

// Reads the file and returns `parseText(text)`; a file that cannot be read is one error, "cannot
// open the file", at the file.
template <class ParseText, class R = std::invoke_result_t<ParseText, const std::string&>>
R parseXmlFile(const std::filesystem::path& path, ParseText&& parseText) {
    Result<std::string> text = readTextFile(path);
    if (!text) return R::failure(std::move(text).diagnostics());
    return parseText(*text);
}

// The folder a file's relative references resolve against: its parent, or "." for a bare name.
inline std::filesystem::path folderOf(const std::filesystem::path& file) {
    return file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
}

}  // namespace rmfx::xml

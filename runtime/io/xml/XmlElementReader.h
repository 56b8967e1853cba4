#pragma once
// Strict reading of rmfx's XML files (workspaces, replay manifests) with tinyxml2: an element's
// attributes are checked against the ones it takes, typed attributes are parsed, and every
// problem becomes a Diagnostic "file:line: error: <element>: message".

#include <algorithm>
#include <array>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tinyxml2.h>

#include "core/Diagnostic.h"
#include "core/Result.h"

namespace rmfx::xml {

using tinyxml2::XMLElement;

// Reads one element: reports attributes it does not know, parses typed attributes, and names
// the element in every diagnostic.
class ElementReader {
public:
    ElementReader(const XMLElement* element, const std::string& file, Diagnostics& diagnostics,
                  std::initializer_list<const char*> allowed);

    SourceLocation where() const { return {file_, element_->GetLineNum()}; }
    // <tag name="…"> when the element has a name attribute, else <tag>.
    std::string label() const;

    void error(const std::string& message) const;
    void warning(const std::string& message) const;

    const char* raw(const char* name) const { return element_->Attribute(name); }
    bool has(const char* name) const { return raw(name) != nullptr; }

    std::optional<std::string> string(const char* name, bool required = false) const;
    // A name that shaders and other elements can refer to: a GLSL identifier.
    std::optional<std::string> identifier(const char* name, bool required = true) const;
    std::optional<float> number(const char* name, bool required = false) const;
    std::optional<int> integer(const char* name, int minimum) const;
    std::optional<bool> boolean(const char* name) const;
    // WIDTHxHEIGHT; `example` is shown in the error.
    std::optional<std::pair<int, int>> size(const char* name, const char* example = "512x512") const;

    template <size_t N>
    std::optional<std::array<float, N>> numbers(const char* name) const {
        auto list = numberList(name, N);
        if (!list) return std::nullopt;
        std::array<float, N> out{};
        std::copy(list->begin(), list->end(), out.begin());
        return out;
    }

    // One of a fixed set of words.
    template <class E>
    std::optional<E> choice(const char* name, std::initializer_list<std::pair<const char*, E>> words) const {
        auto v = string(name);
        if (!v) return std::nullopt;
        for (const auto& [word, value] : words)
            if (*v == word) return value;
        std::string list;
        for (const auto& [word, value] : words) list += std::string(list.empty() ? "" : ", ") + word;
        error("attribute '" + std::string(name) + "': '" + *v + "' is not one of: " + list);
        return std::nullopt;
    }

private:
    std::optional<std::vector<float>> numberList(const char* name, size_t count) const;

    const XMLElement* element_;
    const std::string& file_;
    Diagnostics& diagnostics_;
};

// An error located at an element, with no element label: "unknown element <x> in <y>", say.
void errorAt(const XMLElement* e, const std::string& file, Diagnostics& diagnostics, const std::string& message);
// Reports the first child element of an element that takes none.
void noChildren(const XMLElement* e, const std::string& file, Diagnostics& diagnostics);

// "512x512" → {512, 512}; whole numbers from 1 to 10^6.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

// Parses XML text (named `file` in diagnostics) and returns its root element when the text is
// well-formed and the root is <rootName>; else nullptr with one diagnostic. An element after the
// root is reported and the root still returned, so the caller reports the root's problems too.
const XMLElement* parseDocument(tinyxml2::XMLDocument& doc, const std::string& text, const std::string& file,
                                const char* rootName, Diagnostics& diagnostics);

// A whole file as text; or one error at the file: "the file does not exist", "it is a folder, not a
// file", or "cannot open the file: REASON".
Result<std::string> readTextFile(const std::filesystem::path& path);

}  // namespace rmfx::xml

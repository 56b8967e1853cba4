#pragma once
// Reading one element of a RenderMonkey .rfx file. RenderMonkey writes every attribute its DTD
// declares, most of them irrelevant to rmfx, so unlike xml::ElementReader this reader does not
// reject unknown attributes; it parses the ones asked for and reports bad values as
// "file:line: error: <RmFloatVariable NAME="x">: …".

#include <optional>
#include <string>

#include <tinyxml2.h>

#include "core/Diagnostic.h"

namespace rmfx::rfx {

using tinyxml2::XMLElement;

class RfxElement {
public:
    RfxElement(const XMLElement* element, const std::string& file, Diagnostics& diagnostics)
        : element_(element), file_(&file), diagnostics_(&diagnostics) {}

    const XMLElement* xml() const { return element_; }
    std::string tag() const { return element_->Name(); }
    int line() const { return element_->GetLineNum(); }
    SourceLocation where() const { return {*file_, line()}; }
    // <RmGLPass NAME="Pass 0">, or <RmGLPass> when it has no NAME.
    std::string label() const;
    std::string name() const;  // NAME, "" when absent

    void error(const std::string& message) const;
    void warning(const std::string& message) const;

    bool has(const char* attribute) const { return element_->Attribute(attribute) != nullptr; }
    // The attribute's text; an error when it is required and absent.
    std::optional<std::string> text(const char* attribute, bool required = true) const;
    std::optional<float> number(const char* attribute, bool required = true) const;
    // A whole number in [minimum, maximum].
    std::optional<long long> integer(const char* attribute, long long minimum, long long maximum,
                                     bool required = true) const;
    // TRUE/FALSE (RenderMonkey's spelling; true/false and 1/0 are accepted too).
    std::optional<bool> flag(const char* attribute, bool required = true) const;

    const std::string& file() const { return *file_; }
    Diagnostics& diagnostics() const { return *diagnostics_; }

private:
    const XMLElement* element_;
    const std::string* file_;    // outlives the element (pointers keep RfxElement assignable)
    Diagnostics* diagnostics_;
};

}  // namespace rmfx::rfx

#pragma once
// A small scanner over raw XML text that finds every start tag with the byte offsets of its
// attributes, for edits that must leave the rest of a file byte for byte as it was (tinyxml2
// gives line numbers but no offsets, and rewriting its tree loses formatting and comments).
// Comments, CDATA sections, processing instructions and the DOCTYPE are skipped, so markup
// that only looks like an element there is never reported.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/Result.h"

namespace rmfx::xml {

struct AttributeSpan {
    std::string name;
    size_t begin = 0;       // offset of the attribute's name
    size_t valueBegin = 0;  // first byte inside the quotes
    size_t valueEnd = 0;    // offset of the closing quote
    char quote = '"';
};

struct StartTag {
    std::string name;
    size_t begin = 0;  // offset of '<'
    size_t end = 0;    // one past '>'
    int line = 1;      // of '<', 1-based, counted as tinyxml2 counts ('\n')
    int depth = 0;     // 0: a top-level element (the root)
    int parent = -1;   // index of the enclosing start tag in the scan, -1 at the top level
    bool selfClosing = false;
    std::vector<AttributeSpan> attributes;

    const AttributeSpan* attribute(std::string_view attributeName) const;
};

// Every start tag of the text, in document order. Malformed markup (an unterminated comment or
// tag, an attribute without quotes, a mismatched end tag, an element never closed) is an error
// "FILE:LINE: error: malformed XML: ...".
Result<std::vector<StartTag>> scanStartTags(std::string_view text, const std::string& file);

// An attribute value as the XML parser reads it: the five predefined entities and character
// references are replaced; an unknown reference is kept as written.
std::string decodeAttributeValue(std::string_view raw);

}  // namespace rmfx::xml

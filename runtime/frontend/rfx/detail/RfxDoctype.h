#pragma once
// RenderMonkey writes its DTD inline: <!DOCTYPE RENDER_MONKEY [ <!ELEMENT …> <!ATTLIST …> ]>.
// tinyxml2 ends a DOCTYPE at its first '>', so the internal subset would be read as text.

#include <string>

namespace rmfx::rfx {

// The text with the whole DOCTYPE declaration (internal subset included) turned into spaces,
// newlines kept, so every line number stays what it was. Text without a DOCTYPE, or whose
// DOCTYPE never closes, is returned unchanged (the XML parser then reports it).
std::string blankDoctype(std::string text);

}  // namespace rmfx::rfx

#include "io/xml/XmlElementReader.h"

#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/Value.h"

namespace rmfx::xml {

ElementReader::ElementReader(const XMLElement* element, const std::string& file, Diagnostics& diagnostics,
                             std::initializer_list<const char*> allowed)
    : element_(element), file_(file), diagnostics_(diagnostics) {
    for (const auto* a = element->FirstAttribute(); a; a = a->Next()) {
        bool known = std::any_of(allowed.begin(), allowed.end(),
                                 [&](const char* n) { return std::string_view(n) == a->Name(); });
        if (known) continue;
        std::string list;
        for (const char* n : allowed) list += std::string(list.empty() ? "" : ", ") + n;
        error("unknown attribute '" + std::string(a->Name()) + "'" +
              (list.empty() ? " (it takes none)" : " (expected one of: " + list + ")"));
    }
}

std::string ElementReader::label() const {
    const char* name = element_->Attribute("name");
    return name ? "<" + std::string(element_->Name()) + " name=\"" + name + "\">"
                : "<" + std::string(element_->Name()) + ">";
}

void ElementReader::error(const std::string& message) const {
    diagnostics_.push_back({Diagnostic::Severity::Error, where(), label(), message});
}

void ElementReader::warning(const std::string& message) const {
    diagnostics_.push_back({Diagnostic::Severity::Warning, where(), label(), message});
}

std::optional<std::string> ElementReader::string(const char* name, bool required) const {
    if (const char* v = raw(name)) return std::string(v);
    if (required) error("missing attribute '" + std::string(name) + "'");
    return std::nullopt;
}

std::optional<std::string> ElementReader::identifier(const char* name, bool required) const {
    auto v = string(name, required);
    if (!v) return std::nullopt;
    bool ok = !v->empty() && (std::isalpha(static_cast<unsigned char>((*v)[0])) || (*v)[0] == '_');
    for (char c : *v) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ok) {
        error("attribute '" + std::string(name) + "': '" + *v +
              "' is not a valid name (letters, digits and '_', not starting with a digit)");
        return std::nullopt;
    }
    return v;
}

std::optional<float> ElementReader::number(const char* name, bool required) const {
    auto v = string(name, required);
    if (!v) return std::nullopt;
    auto f = parseFloat(*v);
    if (!f) error("attribute '" + std::string(name) + "': expected a number, got '" + *v + "'");
    return f;
}

std::optional<int> ElementReader::integer(const char* name, int minimum) const {
    auto v = string(name);
    if (!v) return std::nullopt;
    auto f = parseFloat(*v);
    if (!f || *f != std::floor(*f) || *f < minimum || *f > 1e9f) {
        error("attribute '" + std::string(name) + "': expected an integer ≥ " + std::to_string(minimum) + ", got '" +
              *v + "'");
        return std::nullopt;
    }
    return static_cast<int>(*f);
}

std::optional<bool> ElementReader::boolean(const char* name) const {
    auto v = string(name);
    if (!v) return std::nullopt;
    if (*v == "true" || *v == "1") return true;
    if (*v == "false" || *v == "0") return false;
    error("attribute '" + std::string(name) + "': expected true or false, got '" + *v + "'");
    return std::nullopt;
}

std::optional<std::pair<int, int>> ElementReader::size(const char* name, const char* example) const {
    auto v = string(name);
    if (!v) return std::nullopt;
    auto wh = parseSize(*v);
    if (!wh)
        error("attribute '" + std::string(name) + "': expected WIDTHxHEIGHT such as " + example + ", got '" + *v + "'");
    return wh;
}

std::optional<std::vector<float>> ElementReader::numberList(const char* name, size_t count) const {
    auto v = string(name);
    if (!v) return std::nullopt;
    auto list = parseFloatList(*v);
    if (!list || list->size() != count) {
        error("attribute '" + std::string(name) + "': expected " + std::to_string(count) + " numbers, got '" + *v + "'");
        return std::nullopt;
    }
    return list;
}

void errorAt(const XMLElement* e, const std::string& file, Diagnostics& diagnostics, const std::string& message) {
    diagnostics.push_back({Diagnostic::Severity::Error, {file, e->GetLineNum()}, "", message});
}

void noChildren(const XMLElement* e, const std::string& file, Diagnostics& diagnostics) {
    if (const XMLElement* child = e->FirstChildElement())
        errorAt(child, file, diagnostics,
                "unknown element <" + std::string(child->Name()) + "> in <" + e->Name() + "> (it takes no child elements)");
}

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
    auto x = text.find('x');
    if (x == std::string::npos) return std::nullopt;
    auto w = parseFloat(text.substr(0, x)), h = parseFloat(text.substr(x + 1));
    if (!w || !h || *w < 1 || *h < 1 || *w != std::floor(*w) || *h != std::floor(*h) || *w > 1e6f || *h > 1e6f)
        return std::nullopt;
    return std::pair{static_cast<int>(*w), static_cast<int>(*h)};
}

namespace {

// tinyxml2's ErrorStr() is "Error=XML_ERROR_… ErrorID=… (0x…) Line number=…[: XMLElement name=…]", which
// says neither what is wrong nor how to fix it; say it in words.
std::string xmlErrorSentence(const tinyxml2::XMLDocument& doc) {
    std::string raw = doc.ErrorStr() ? doc.ErrorStr() : "";
    std::string element;
    if (auto at = raw.find("XMLElement name="); at != std::string::npos) element = raw.substr(at + 16);
    switch (doc.ErrorID()) {
        case tinyxml2::XML_ERROR_EMPTY_DOCUMENT: return "the file has no element";
        case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
            return "<" + element + "> is not closed (its end tag is missing, misspelled or out of order)";
        case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
            return "bad attribute in <" + element + "> (write name=\"value\", each name once)";
        case tinyxml2::XML_ERROR_PARSING_ELEMENT: return "bad element syntax (a stray '<'? in text write &lt;)";
        case tinyxml2::XML_ERROR_PARSING_TEXT: return "bad text (a '<' or '&' that should be &lt; or &amp;?)";
        case tinyxml2::XML_ERROR_PARSING_CDATA: return "<![CDATA[ without its closing ]]>";
        case tinyxml2::XML_ERROR_PARSING_COMMENT: return "<!-- without its closing -->";
        case tinyxml2::XML_ERROR_PARSING_DECLARATION: return "bad <?…?> declaration";
        case tinyxml2::XML_ERROR_PARSING_UNKNOWN: return "bad <!…> construct";
        case tinyxml2::XML_ERROR_PARSING:
            return "cannot read the document from here on (an element left open at the end of the file?)";
        default: return doc.ErrorName();
    }
}

}  // namespace

const XMLElement* parseDocument(tinyxml2::XMLDocument& doc, const std::string& text, const std::string& file,
                                const char* rootName, Diagnostics& diagnostics) {
    if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
        diagnostics.push_back(
            {Diagnostic::Severity::Error, {file, doc.ErrorLineNum()}, "", "malformed XML: " + xmlErrorSentence(doc)});
        return nullptr;
    }
    const XMLElement* root = doc.RootElement();
    if (!root || std::string_view(root->Name()) != rootName) {
        diagnostics.push_back({Diagnostic::Severity::Error, {file, root ? root->GetLineNum() : 1}, "",
                               "the root element must be <" + std::string(rootName) + ">" +
                                   (root ? ", not <" + std::string(root->Name()) + ">" : std::string())});
        return nullptr;
    }
    // tinyxml2 accepts several top-level elements; everything after the first would be ignored.
    if (const XMLElement* extra = root->NextSiblingElement())
        errorAt(extra, file, diagnostics,
                "<" + std::string(extra->Name()) + "> after </" + rootName + ">: a file holds one <" + rootName + ">");
    return root;
}

Result<std::string> readTextFile(const std::filesystem::path& path) {
    auto failure = [&](std::string why) {
        return Result<std::string>::failure({{Diagnostic::Severity::Error, {path.string(), 0}, "", std::move(why)}});
    };
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) return failure("the file does not exist");
    if (status.type() == std::filesystem::file_type::directory) return failure("it is a folder, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int error = errno;
        return failure(std::string("cannot open the file") + (error ? std::string(": ") + std::strerror(error) : ""));
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

}  // namespace rmfx::xml

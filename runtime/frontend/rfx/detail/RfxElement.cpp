#include "frontend/rfx/detail/RfxElement.h"

#include <charconv>
#include <cmath>

#include "core/Value.h"

namespace rmfx::rfx {

std::string RfxElement::label() const {
    const char* n = element_->Attribute("NAME");
    return "<" + tag() + (n ? " NAME=\"" + std::string(n) + "\"" : std::string()) + ">";
}

std::string RfxElement::name() const {
    const char* n = element_->Attribute("NAME");
    return n ? n : "";
}

void RfxElement::error(const std::string& message) const {
    diagnostics_->push_back({Diagnostic::Severity::Error, where(), label(), message});
}

void RfxElement::warning(const std::string& message) const {
    diagnostics_->push_back({Diagnostic::Severity::Warning, where(), label(), message});
}

std::optional<std::string> RfxElement::text(const char* attribute, bool required) const {
    const char* v = element_->Attribute(attribute);
    if (!v) {
        if (required) error("the attribute " + std::string(attribute) + " is missing");
        return std::nullopt;
    }
    return std::string(v);
}

std::optional<float> RfxElement::number(const char* attribute, bool required) const {
    auto v = text(attribute, required);
    if (!v) return std::nullopt;
    auto n = parseFloat(*v);
    if (!n || !std::isfinite(*n)) {
        error("attribute " + std::string(attribute) + ": '" + *v + "' is not a number");
        return std::nullopt;
    }
    return n;
}

std::optional<long long> RfxElement::integer(const char* attribute, long long minimum, long long maximum,
                                             bool required) const {
    auto v = text(attribute, required);
    if (!v) return std::nullopt;
    long long n = 0;
    const char* begin = v->data();
    const char* end = begin + v->size();
    while (begin < end && *begin == ' ') ++begin;
    while (end > begin && end[-1] == ' ') --end;
    auto [ptr, ec] = std::from_chars(begin, end, n);
    if (ec != std::errc() || ptr != end || begin == end) {
        error("attribute " + std::string(attribute) + ": '" + *v + "' is not a whole number");
        return std::nullopt;
    }
    if (n < minimum || n > maximum) {
        error("attribute " + std::string(attribute) + ": " + std::to_string(n) + " is outside " +
              std::to_string(minimum) + "…" + std::to_string(maximum));
        return std::nullopt;
    }
    return n;
}

std::optional<bool> RfxElement::flag(const char* attribute, bool required) const {
    auto v = text(attribute, required);
    if (!v) return std::nullopt;
    if (*v == "TRUE" || *v == "true" || *v == "1") return true;
    if (*v == "FALSE" || *v == "false" || *v == "0") return false;
    error("attribute " + std::string(attribute) + ": '" + *v + "' is not TRUE or FALSE");
    return std::nullopt;
}

}  // namespace rmfx::rfx

// ReshadeParserRun's structs, functions and the attributes before them: fields and parameters with
// their qualifiers and semantics, default arguments, and a function's body as a span of the code
// with its braces matched.
#include "frontend/reshade/ReshadeParserRun.h"

#include <algorithm>

namespace rmfx {
namespace {

using DK = ReshadeDeclaration::Kind;

}  // namespace

void ReshadeParserRun::parseStruct() {
    c_.next();
    const SourceLocation where = c_.here();
    std::optional<std::string> name = c_.expectIdentifier("struct", "a struct name");
    if (!name) return recover();
    ReshadeStruct s;
    s.name = qualify(*name);
    s.where = where;
    const std::string element = "struct " + s.name;
    // Declared before its fields, so that a field names it in an error the same way.
    if (!c_.expect("{", element)) return recover();
    while (!c_.atEnd() && !c_.is("}")) {
        const size_t before = c_.position();
        ReshadeField first;
        if (!parseField(first, element, false)) {
            skipUntil(";");
            c_.accept(";");
            if (c_.position() == before) c_.next();
            continue;
        }
        s.fields.push_back(first);
        while (c_.accept(",")) {
            ReshadeField more;
            more.type = first.type;
            more.qualifiers = first.qualifiers;
            more.where = c_.here();
            std::optional<std::string> field = c_.expectIdentifier(element, "a field name");
            if (!field) break;
            more.name = *field;
            parseArraySize(more.type, element);
            if (c_.accept(":"))
                if (std::optional<std::string> semantic = c_.expectIdentifier(element, "a semantic")) more.semantic = *semantic;
            s.fields.push_back(more);
        }
        if (!c_.expect(";", element)) skipUntil(";"), c_.accept(";");
    }
    if (!c_.expect("}", element)) return;
    c_.expect(";", element);
    if (s.fields.empty()) c_.warning(where, element, "the struct has no fields");
    const size_t index = effect_.structs.size();
    if (!declare(s.name, {DK::Struct, index, where}, element)) return;
    effect_.structs.push_back(std::move(s));
    addDeclaration(DK::Struct, index);
}

bool ReshadeParserRun::parseField(ReshadeField& field, const std::string& element, bool parameter) {
    field.qualifiers = parseQualifiers();
    std::optional<ReshadeType> type = parseType(element);
    if (!type) return false;
    field.type = *type;
    field.where = c_.here();
    std::optional<std::string> name = c_.expectIdentifier(element, parameter ? "a parameter name" : "a field name");
    if (!name) return false;
    field.name = *name;
    if (!parseArraySize(field.type, element)) return false;
    if (c_.accept(":")) {
        std::optional<std::string> semantic = c_.expectIdentifier(element, "a semantic");
        if (!semantic) return false;
        field.semantic = *semantic;
    }
    return true;
}

std::vector<ReshadeAttribute> ReshadeParserRun::parseAttributes() {
    std::vector<ReshadeAttribute> attributes;
    while (c_.is("[")) {
        c_.next();
        ReshadeAttribute a;
        a.where = c_.here();
        std::optional<std::string> name = c_.expectIdentifier("", "an attribute name");
        if (!name) break;
        a.name = *name;
        if (c_.accept("(")) {
            while (!c_.atEnd() && !c_.is(")")) {
                if (!a.arguments.empty() && !c_.expect(",", "attribute " + a.name)) break;
                std::string error;
                std::optional<ReshadeValue> v = readReshadeConstant(c_, lookup(), error);
                if (!v) {
                    c_.error(a.where, "attribute " + a.name, error);
                    break;
                }
                a.arguments.push_back(std::move(*v));
            }
            if (!c_.expect(")", "attribute " + a.name)) break;
        }
        if (!c_.expect("]", "attribute " + a.name)) break;
        attributes.push_back(std::move(a));
    }
    return attributes;
}

void ReshadeParserRun::parseFunction(const ReshadeType& returnType, const std::string& name, const SourceLocation& where,
                                     std::vector<ReshadeAttribute> attributes) {
    ReshadeFunction f;
    f.attributes = std::move(attributes);
    f.name = qualify(name);
    f.returnType = returnType;
    f.where = where;
    const std::string element = "function " + f.name;
    c_.next();  // (
    if (c_.is("void") && c_.is(")", 1)) c_.next();
    while (!c_.atEnd() && !c_.is(")")) {
        if (!f.parameters.empty() && !c_.expect(",", element)) break;
        ReshadeField p;
        if (!parseField(p, element, true)) break;
        if (!(p.qualifiers & kReshadeOut)) p.qualifiers |= kReshadeIn;
        if (p.type.base == ReshadeBaseType::Void) c_.error(p.where, element, "parameter '" + p.name + "' cannot be void");
        if (c_.accept("=")) {  // a default argument
            std::string error;
            const SourceLocation at = c_.here();
            p.defaultValue = readReshadeConstant(c_, lookup(), error);
            if (!p.defaultValue) {
                c_.error(at, element, "the default value of parameter '" + p.name + "' is not a constant: " + error);
                break;
            }
            p.defaultValue = fitToType(*p.defaultValue, p.type);
        } else if (!f.parameters.empty() && f.parameters.back().defaultValue) {
            c_.error(p.where, element, "parameter '" + p.name + "' needs a default value, as the parameters before it have");
        }
        f.parameters.push_back(std::move(p));
    }
    if (!c_.expect(")", element)) {
        skipUntil(")");
        c_.accept(")");
    }
    if (c_.accept(":"))
        if (std::optional<std::string> semantic = c_.expectIdentifier(element, "a semantic")) f.returnSemantic = *semantic;
    if (c_.is(";")) {
        c_.error(where, element, "a function needs a body (ReShade has no declarations without one)");
        c_.next();
        return;
    }
    if (!c_.is("{")) {
        c_.error(c_.here(), element, "expected '{', found " + c_.describe(c_.peek()));
        return recover();
    }
    // The body: its braces matched, nothing more.
    const ReshadeToken open = c_.next();
    f.body.begin = open.offset;
    f.body.where = c_.where(open);
    for (size_t depth = 1; depth > 0;) {
        if (c_.atEnd()) {
            c_.error(f.body.where, element, "the function's '{' is never closed");
            f.body.end = c_.code().size();
            break;
        }
        const ReshadeToken& t = c_.next();
        if (c_.text(t) == "{") ++depth;
        else if (c_.text(t) == "}" && --depth == 0) f.body.end = t.offset + 1;
    }
    std::vector<std::string> signature;
    for (const ReshadeField& p : f.parameters) signature.push_back(p.type.name + "[" + std::to_string(p.type.arrayLength) + "]");
    std::vector<std::vector<std::string>>& overloads = overloads_[f.name];
    if (std::find(overloads.begin(), overloads.end(), signature) != overloads.end()) {
        const Symbol* first = resolve("::" + f.name, DK::Function);
        c_.error(where, element,
                 "redefinition of '" + f.name + "' with the same parameters" +
                     (first ? " (at " + first->where.file + ":" + std::to_string(first->where.line) + ")" : ""));
        return;
    }
    const size_t index = effect_.functions.size();
    if (!declare(f.name, {DK::Function, index, where}, element)) return;
    overloads.push_back(std::move(signature));
    effect_.functions.push_back(std::move(f));
    addDeclaration(DK::Function, index);
}

}  // namespace rmfx

#include "frontend/reshade/ReshadeParser.h"

#include "frontend/reshade/ReshadeLexer.h"
#include "frontend/reshade/ReshadeParserRun.h"

#include <algorithm>
#include <cctype>

namespace rmfx {
namespace {

using TK = ReshadeToken::Kind;
using DK = ReshadeDeclaration::Kind;

constexpr size_t kMaxTokens = size_t(4) << 20;

}  // namespace

bool ReshadeParserRun::startsDeclaration(std::string_view word) {
    static constexpr std::string_view kWords[] = {"uniform", "static",  "texture",   "texture1D", "texture2D", "texture3D",
                                                  "sampler", "sampler1D", "sampler2D", "sampler3D", "storage", "storage1D",
                                                  "storage2D", "storage3D", "technique", "namespace", "struct"};
    return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}

namespace {

ReshadeValue::Kind kindOf(const ReshadeType& type) {
    switch (type.base) {
        case ReshadeBaseType::Bool: return ReshadeValue::Kind::Bool;
        case ReshadeBaseType::Int: return ReshadeValue::Kind::Int;
        case ReshadeBaseType::Uint: return ReshadeValue::Kind::Uint;
        case ReshadeBaseType::String: return ReshadeValue::Kind::String;
        default: return ReshadeValue::Kind::Float;
    }
}

const char* kindName(DK kind) {
    switch (kind) {
        case DK::Uniform: return "uniform";
        case DK::Texture: return "texture";
        case DK::Sampler: return "sampler";
        case DK::Storage: return "storage";
        case DK::Struct: return "struct";
        case DK::Variable: return "variable";
        case DK::Function: return "function";
        case DK::Technique: return "technique";
    }
    return "";
}

}  // namespace

ReshadeEffect parseReshadeEffect(const PreprocessedReshade& source, Diagnostics& diagnostics) {
    ReshadeLexed lexed = lexReshade(source.code, kMaxTokens);
    if (lexed.tooMany) {
        const ReshadeToken& last = lexed.tokens.back();
        diagnostics.push_back({Diagnostic::Severity::Error, source.origin(last.line), "",
                               "the effect has more than " + std::to_string(kMaxTokens) + " tokens; the rest is not read"});
    }
    ReshadeParserRun run(source, std::move(lexed.tokens), diagnostics);
    return run.run();
}

ReshadeValue ReshadeParserRun::fitToType(const ReshadeValue& value, ReshadeType& type) {
    if (!value.isNumber() || !type.isNumeric()) return value;
    ReshadeValue out = convertReshadeValue(value, kindOf(type));
    const size_t each = static_cast<size_t>(type.rows * type.cols);
    if (type.arrayLength == 0 && out.components.size() == 1 && each > 1) out.components.assign(each, out.components[0]);
    if (type.arrayLength < 0 && each > 0) type.arrayLength = static_cast<int>(out.components.size() / each);
    return out;
}

ReshadeEffect ReshadeParserRun::run() {
    while (!c_.atEnd()) {
        topLevel(0);
        if (c_.is("}")) {
            c_.error(c_.here(), "", "unexpected '}' (no '{' or namespace is open)");
            c_.next();
        }
    }
    return std::move(effect_);
}

void ReshadeParserRun::topLevel(int depth) {
    while (!c_.atEnd() && !c_.is("}")) {
        const size_t before = c_.position();
        const ReshadeToken& t = c_.peek();
        if (c_.accept(";")) continue;
        if (t.kind == TK::Bad) {
            c_.error(c_.here(), "", "unexpected character " + c_.describe(t));
            c_.next();
            continue;
        }
        if (c_.is("namespace")) parseNamespace(depth);
        else if (c_.is("struct")) parseStruct();
        else if (c_.is("technique")) parseTechnique();
        else parseDeclaration();
        if (c_.position() == before) c_.next();  // always move on
    }
}

void ReshadeParserRun::parseNamespace(int depth) {
    const SourceLocation where = c_.here();
    c_.next();
    std::optional<std::string> name = c_.expectIdentifier("namespace", "a namespace name");
    if (!name) return recover();
    const std::string element = "namespace " + qualify(*name);
    if (depth + 1 >= kMaxNamespaceDepth) {
        c_.error(where, element, "namespaces nest more than " + std::to_string(kMaxNamespaceDepth) + " deep");
        c_.abandon();
        return;
    }
    if (!c_.expect("{", element)) return recover();
    const std::string outer = namespace_;
    namespace_ += *name + "::";
    topLevel(depth + 1);
    namespace_ = outer;
    if (!c_.accept("}")) c_.error(where, element, "the namespace's '{' is never closed");
}

unsigned ReshadeParserRun::parseQualifiers() {
    struct Word {
        std::string_view word;
        unsigned bits;
    };
    static constexpr Word kWords[] = {{"static", kReshadeStatic},
                                      {"const", kReshadeConst},
                                      {"uniform", kReshadeUniform},
                                      {"extern", kReshadeExtern},
                                      {"groupshared", kReshadeGroupshared},
                                      {"volatile", kReshadeVolatile},
                                      {"precise", kReshadePrecise},
                                      {"in", kReshadeIn},
                                      {"out", kReshadeOut},
                                      {"inout", kReshadeIn | kReshadeOut},
                                      {"linear", kReshadeLinear},
                                      {"noperspective", kReshadeNoPerspective},
                                      {"centroid", kReshadeCentroid},
                                      {"nointerpolation", kReshadeNoInterpolation},
                                      {"shared", 0},
                                      {"inline", 0},
                                      {"row_major", 0},
                                      {"column_major", 0},
                                      {"unorm", 0},
                                      {"snorm", 0}};
    unsigned bits = 0;
    for (bool found = true; found;) {
        found = false;
        for (const Word& w : kWords)
            if (c_.isKind(TK::Identifier) && c_.peekText() == w.word) {
                c_.next();
                bits |= w.bits;
                found = true;
            }
    }
    return bits;
}

std::optional<ReshadeType> ReshadeParserRun::parseType(const std::string& element) {
    if (!c_.isKind(TK::Identifier) && !c_.is("::")) {
        c_.error(c_.here(), element, "expected a type, found " + c_.describe(c_.peek()));
        return std::nullopt;
    }
    const std::string word(c_.peekText());
    if (std::optional<ReshadeType> numeric = reshadeNumericType(word)) {
        c_.next();
        return numeric;
    }
    ReshadeType type;
    type.name = word;
    if (word == "void" || word == "string") {
        c_.next();
        type.base = word == "void" ? ReshadeBaseType::Void : ReshadeBaseType::String;
        return type;
    }
    if (word == "vector" || word == "matrix") {
        c_.next();
        if (!c_.expect("<", element)) return std::nullopt;
        std::optional<ReshadeType> scalar = reshadeNumericType(c_.peekText());
        if (!scalar || scalar->rows != 1 || scalar->cols != 1) {
            c_.error(c_.here(), element, "expected a scalar type, found " + c_.describe(c_.peek()));
            return std::nullopt;
        }
        c_.next();
        int sizes[2] = {1, 1};
        for (int k = 0; k < (word == "matrix" ? 2 : 1); ++k) {
            std::string error;
            if (!c_.expect(",", element)) return std::nullopt;
            std::optional<ReshadeValue> n = readReshadeConstant(c_, lookup(), error, true);
            if (!n || !n->isNumber() || n->at() < 1 || n->at() > 4) {
                c_.error(c_.here(), element, "the size of a " + word + " is 1 to 4");
                return std::nullopt;
            }
            sizes[k] = static_cast<int>(n->at());
        }
        if (!c_.expect(">", element)) return std::nullopt;
        type.base = scalar->base;
        type.rows = sizes[0];
        type.cols = sizes[1];
        return type;
    }
    struct Object {
        std::string_view prefix;
        ReshadeBaseType base;
    };
    for (const Object& o : {Object{"texture", ReshadeBaseType::Texture}, Object{"sampler", ReshadeBaseType::Sampler},
                            Object{"storage", ReshadeBaseType::Storage}}) {
        if (word.rfind(o.prefix, 0) != 0) continue;
        const std::string rest = word.substr(o.prefix.size());
        if (!(rest.empty() || rest == "1D" || rest == "2D" || rest == "3D")) continue;
        c_.next();
        type.base = o.base;
        type.dimensions = rest.empty() ? 2 : rest[0] - '0';
        if (c_.accept("<")) {
            std::optional<std::string> element_ = c_.expectIdentifier(element, "an element type");
            if (!element_ || !c_.expect(">", element)) return std::nullopt;
            type.element = *element_;
        }
        return type;
    }
    // A struct, by its name as written
    const size_t start = c_.position();
    const std::string written = readQualifiedName();
    const Symbol* symbol = resolve(written, DK::Struct);
    if (symbol && symbol->kind == DK::Struct) {
        type.base = ReshadeBaseType::Struct;
        type.name = effect_.structs[symbol->index].name;
        return type;
    }
    c_.seek(start);
    c_.error(c_.here(), element, (symbol ? "'" + written + "' is not a type" : "unknown type '" + written + "'"));
    return std::nullopt;
}

std::string ReshadeParserRun::readQualifiedName() {
    std::string name;
    if (c_.accept("::")) name = "::";
    while (c_.isKind(TK::Identifier)) {
        name += c_.text(c_.next());
        if (!(c_.is("::") && c_.isKind(TK::Identifier, 1))) break;
        c_.next();
        name += "::";
    }
    return name;
}

bool ReshadeParserRun::parseArraySize(ReshadeType& type, const std::string& element) {
    if (!c_.accept("[")) return true;
    if (c_.accept("]")) {
        type.arrayLength = -1;
        return true;
    }
    std::string error;
    const SourceLocation where = c_.here();
    std::optional<ReshadeValue> n = readReshadeConstant(c_, lookup(), error);
    if (!n || !n->isNumber() || n->at() < 1 || n->at() > 65536) {
        c_.error(where, element, n ? "an array's size must be 1 to 65536" : "the array size is not a constant: " + error);
        skipUntil("]");
        c_.accept("]");
        return false;
    }
    type.arrayLength = static_cast<int>(n->at());
    return c_.expect("]", element);
}

void ReshadeParserRun::parseDeclaration() {
    std::vector<ReshadeAttribute> attributes = parseAttributes();
    const unsigned qualifiers = parseQualifiers();
    std::optional<ReshadeType> type = parseType("");
    if (!type) return recover();
    const SourceLocation where = c_.here();
    std::optional<std::string> name = c_.expectIdentifier("", "a name after '" + type->name + "'");
    if (!name) return recover();
    if (c_.is("(")) {
        if (qualifiers & ~(kReshadeStatic | kReshadePrecise))
            c_.error(where, "function " + qualify(*name), "a function's return type cannot have qualifiers");
        return parseFunction(*type, *name, where, std::move(attributes));
    }
    if (!attributes.empty()) c_.error(attributes.front().where, "", "attributes come before functions only");
    std::string element = parseGlobal(*type, qualifiers, *name, where);
    while (c_.accept(",")) {
        const SourceLocation next = c_.here();
        std::optional<std::string> more = c_.expectIdentifier(element, "a name after ','");
        if (!more) return recover();
        element = parseGlobal(*type, qualifiers, *more, next);
    }
    if (!c_.expect(";", element)) recover();
}

std::string ReshadeParserRun::parseGlobal(ReshadeType type, unsigned qualifiers, const std::string& name,
                                          const SourceLocation& where) {
    const std::string qualified = qualify(name);
    if (type.base == ReshadeBaseType::Texture) return parseTexture(type, qualified, where), "texture " + qualified;
    if (type.base == ReshadeBaseType::Sampler) return parseSampler(type, qualified, where), "sampler " + qualified;
    if (type.base == ReshadeBaseType::Storage) return parseStorage(type, qualified, where), "storage " + qualified;
    const bool isUniform = !(qualifiers & (kReshadeStatic | kReshadeGroupshared));
    const std::string element = (isUniform ? "uniform " : "variable ") + qualified;
    if (type.base == ReshadeBaseType::Void) c_.error(where, element, "a variable cannot be void");
    if (qualifiers & (kReshadeIn | kReshadeOut)) c_.error(where, element, "a global cannot be 'in' or 'out'");
    parseArraySize(type, element);
    std::string semantic;
    if (c_.accept(":"))
        if (std::optional<std::string> s = c_.expectIdentifier(element, "a semantic")) semantic = *s;
    ReshadeAnnotations annotations = parseAnnotations(element);
    ReshadeSpan span;
    std::optional<ReshadeValue> value;
    if (c_.accept("=")) {
        value = parseInitializer(element, isUniform, span);
        if (value) value = fitToType(*value, type);
    }
    if (type.arrayLength < 0 && !value) c_.error(where, element, "an array without a size needs an initial value");
    if (isUniform) {
        ReshadeUniform u;
        u.name = qualified;
        u.type = type;
        u.qualifiers = qualifiers | kReshadeUniform;
        u.implicit = !(qualifiers & kReshadeUniform);
        u.annotations = std::move(annotations);
        u.initializer = std::move(value);
        u.where = where;
        if (qualifiers & kReshadeConst) c_.error(where, element, "a uniform cannot be 'const' (write 'static const' for a constant)");
        else if (u.implicit) c_.warning(where, element, "a global without 'static' is a uniform, as if declared 'uniform'");
        const size_t index = effect_.uniforms.size();
        if (!declare(qualified, {DK::Uniform, index, where}, element)) return element;
        effect_.uniforms.push_back(std::move(u));
        addDeclaration(DK::Uniform, index);
        return element;
    }
    ReshadeVariable v;
    v.name = qualified;
    v.type = type;
    v.qualifiers = qualifiers;
    v.value = std::move(value);
    v.initializer = span;
    v.where = where;
    if ((qualifiers & kReshadeConst) && span.empty()) c_.error(where, element, "a constant needs an initial value");
    if ((qualifiers & kReshadeGroupshared) && !span.empty()) c_.error(where, element, "a groupshared variable cannot have an initial value");
    const size_t index = effect_.variables.size();
    if (!declare(qualified, {DK::Variable, index, where}, element)) return element;
    effect_.variables.push_back(std::move(v));
    addDeclaration(DK::Variable, index);
    return element;
}

std::optional<ReshadeValue> ReshadeParserRun::parseInitializer(const std::string& element, bool required, ReshadeSpan& span) {
    // Its extent: up to ';' or ',' outside brackets.
    size_t end = c_.position();
    for (int depth = 0;; ++end) {
        const ReshadeToken& t = c_.token(end);
        if (t.kind == TK::End || end >= c_.limit()) break;
        const std::string_view text = c_.text(t);
        if (t.kind == TK::Punct) {
            if (text == "(" || text == "[" || text == "{") ++depth;
            else if (text == ")" || text == "]" || text == "}") {
                if (depth == 0) break;
                --depth;
            } else if (depth == 0 && (text == ";" || text == ",")) break;
        } else if (depth == 0 && t.kind == TK::Identifier && startsDeclaration(text) && t.line != c_.peek().line) {
            break;  // a missing ';': the next declaration
        }
    }
    const SourceLocation where = c_.here();
    if (end == c_.position()) {
        c_.error(where, element, "expected an initial value, found " + c_.describe(c_.peek()));
        return std::nullopt;
    }
    span.begin = c_.peek().offset;
    span.end = c_.token(end - 1).offset + c_.token(end - 1).length;
    span.where = where;
    const size_t savedLimit = c_.limit();
    c_.setLimit(end);
    std::string error;
    std::optional<ReshadeValue> value = readReshadeConstant(c_, lookup(), error);
    if (value && !c_.atEnd()) {
        value.reset();
        error = "unexpected " + c_.describe(c_.peek());
    }
    c_.setLimit(savedLimit);
    c_.seek(end);
    if (!value && required) c_.error(where, element, "the initial value is not a constant rmfx computes: " + error);
    return value;
}

ReshadeAnnotations ReshadeParserRun::parseAnnotations(const std::string& element) {
    ReshadeAnnotations annotations;
    if (!c_.accept("<")) return annotations;
    while (!c_.atEnd() && !c_.is(">")) {
        if (c_.isKind(TK::Identifier) && c_.isKind(TK::Identifier, 1)) c_.next();  // a type before the name: `string ui_label`
        ReshadeAnnotation a;
        a.where = c_.here();
        std::optional<std::string> name = c_.expectIdentifier(element, "an annotation name");
        if (!name || !c_.expect("=", element)) {
            skipUntil(">");
            break;
        }
        a.name = *name;
        std::string error;
        std::optional<ReshadeValue> value = readReshadeConstant(c_, lookup(), error, true);
        if (!value) {
            c_.error(a.where, element, "annotation '" + a.name + "': " + error);
            skipUntil(";");
        } else {
            a.value = std::move(*value);
            if (findAnnotation(annotations, a.name)) c_.warning(a.where, element, "annotation '" + a.name + "' is given twice; the last counts");
            std::erase_if(annotations, [&](const ReshadeAnnotation& o) { return o.name == a.name; });
            annotations.push_back(std::move(a));
        }
        if (!c_.expect(";", element)) {
            skipUntil(">");
            break;
        }
    }
    c_.expect(">", element);
    return annotations;
}

void ReshadeParserRun::skipUntil(std::string_view stop) {
    int depth = 0;
    while (!c_.atEnd()) {
        if (depth == 0 && c_.is(stop)) return;
        if (c_.is("(") || c_.is("[") || c_.is("{")) ++depth;
        else if (c_.is(")") || c_.is("]") || c_.is("}")) {
            if (depth == 0) return;
            --depth;
        }
        c_.next();
    }
}

void ReshadeParserRun::recover() {
    int depth = 0;
    const int line = c_.previous().line;
    while (!c_.atEnd()) {
        const ReshadeToken& t = c_.peek();
        if (depth == 0 && c_.is(";")) {
            c_.next();
            return;
        }
        if (depth == 0 && t.kind == TK::Identifier && startsDeclaration(c_.text(t)) && t.line != line) return;
        if (c_.is("(") || c_.is("[") || c_.is("{")) ++depth;
        else if (c_.is(")") || c_.is("]") || c_.is("}")) {
            if (depth == 0) return;
            if (--depth == 0 && c_.is("}")) {
                c_.next();
                c_.accept(";");
                return;
            }
        }
        c_.next();
    }
}

bool ReshadeParserRun::declare(const std::string& qualified, Symbol symbol, const std::string& element) {
    std::vector<Symbol>& entries = symbols_[qualified];
    // A function may share its name, as in ReShade: with its overloads (their parameters are
    // checked apart) and with a variable declared before it (`static const float3x3 M` and M(x)).
    for (const Symbol& s : symbol.kind == DK::Function ? std::vector<Symbol>{} : entries) {
        c_.error(symbol.where, element,
                 "redefinition of '" + qualified + "' (a " + kindName(s.kind) + " at " + s.where.file + ":" +
                     std::to_string(s.where.line) + ")");
        return false;
    }
    entries.push_back(symbol);
    return true;
}

const ReshadeParserRun::Symbol* ReshadeParserRun::resolve(const std::string& written, std::optional<ReshadeDeclaration::Kind> want) const {
    auto pick = [&](const std::vector<Symbol>& entries) -> const Symbol* {
        for (const Symbol& s : entries)
            if (want && s.kind == *want) return &s;
        return entries.empty() ? nullptr : &entries.front();
    };
    if (written.rfind("::", 0) == 0) {
        auto it = symbols_.find(written.substr(2));
        return it == symbols_.end() ? nullptr : pick(it->second);
    }
    std::string scope = namespace_;
    for (;;) {
        auto it = symbols_.find(scope + written);
        if (it != symbols_.end() && !it->second.empty()) return pick(it->second);
        if (scope.empty()) return nullptr;
        scope.resize(scope.size() - 2);
        const size_t cut = scope.rfind("::");
        scope.resize(cut == std::string::npos ? 0 : cut + 2);
    }
}

std::optional<ReshadeValue> ReshadeParserRun::constantNamed(const std::string& written) const {
    const Symbol* symbol = resolve(written, DK::Variable);
    if (!symbol || symbol->kind != DK::Variable) return std::nullopt;
    const ReshadeVariable& v = effect_.variables[symbol->index];
    if (!(v.qualifiers & kReshadeConst)) return std::nullopt;
    return v.value;
}

std::optional<ReshadeValue> ReshadeParserRun::readStateValue(const ReshadeEnum* table, const std::string& state,
                                                            const std::string& element) {
    const SourceLocation where = c_.here();
    if (table) {
        const std::string word(c_.peekText());
        if (c_.isKind(TK::Identifier) && !c_.is("::", 1)) {
            if (std::optional<int> value = table->find(word)) {
                c_.next();
                return ReshadeValue::number(ReshadeValue::Kind::Int, *value);
            }
        }
        const size_t start = c_.position();
        std::string error;
        (void)readReshadeConstant(c_, lookup(), error);
        std::string written = word;
        if (c_.position() > start) {
            const size_t begin = c_.token(start).offset;
            written = c_.code().substr(begin, c_.previous().offset + c_.previous().length - begin);
        }
        c_.error(where, element,
                 "'" + written + "' is not a " + std::string(table->what()) + " for " + state + " (expected " + table->list() + ")");
        return std::nullopt;
    }
    std::string error;
    std::optional<ReshadeValue> v = readReshadeConstant(c_, lookup(), error);
    if (!v) c_.error(where, element, state + ": " + error);
    else if (!v->isNumber() || v->components.size() != 1) {
        c_.error(where, element, state + ": expected a number, found " + v->describe());
        return std::nullopt;
    }
    return v;
}

std::optional<std::string> ReshadeParserRun::readTextureName(const std::string& element) {
    const SourceLocation where = c_.here();
    if (!c_.isKind(TK::Identifier) && !c_.is("::")) {
        c_.error(where, element, "expected a texture name, found " + c_.describe(c_.peek()));
        return std::nullopt;
    }
    const std::string written = readQualifiedName();
    const Symbol* symbol = resolve(written, DK::Texture);
    if (!symbol) c_.error(where, element, "undeclared identifier '" + written + "', expected a texture");
    else if (symbol->kind != DK::Texture) c_.error(where, element, "'" + written + "' is a " + kindName(symbol->kind) + ", not a texture");
    else return effect_.textures[symbol->index].name;
    return std::nullopt;
}

}  // namespace rmfx

#pragma once
// One run of the ReShade FX parser (ReshadeParser.h), shared by the files that implement it:
// ReshadeParser.cpp (the top level: namespaces, globals, annotations, names), ReshadeFunctions.cpp
// (structs, functions), ReshadeObjects.cpp (textures, samplers, storages) and ReshadeTechniques.cpp
// (techniques, passes).
// Internal to the parser.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frontend/reshade/ReshadeConstant.h"
#include "frontend/reshade/ReshadeCursor.h"
#include "frontend/reshade/ReshadeStates.h"
#include "frontend/reshade/ReshadeSyntax.h"

namespace rmfx {

class ReshadeParserRun {
public:
    static constexpr int kMaxNamespaceDepth = 32;

    ReshadeParserRun(const PreprocessedReshade& source, std::vector<ReshadeToken> tokens, Diagnostics& diagnostics)
        : c_(source, std::move(tokens), diagnostics) {}

    ReshadeEffect run();

private:
    struct Symbol {
        ReshadeDeclaration::Kind kind;
        size_t index;
        SourceLocation where;
    };

    // ReshadeParser.cpp
    void topLevel(int depth);
    void parseNamespace(int depth);
    void parseDeclaration();
    unsigned parseQualifiers();
    std::optional<ReshadeType> parseType(const std::string& element);
    bool parseArraySize(ReshadeType& type, const std::string& element);

    // An initializer's value for a variable of `type`: converted to its kind, a scalar spread over
    // a vector, an unsized array's length taken from it.
    static ReshadeValue fitToType(const ReshadeValue& value, ReshadeType& type);
    // Returns the declaration's element ("uniform Ns::X"), for what follows it.
    std::string parseGlobal(ReshadeType type, unsigned qualifiers, const std::string& name, const SourceLocation& where);
    ReshadeAnnotations parseAnnotations(const std::string& element);
    // The initializer after '=': its value when constant (else an error when `required`), and its text.
    std::optional<ReshadeValue> parseInitializer(const std::string& element, bool required, ReshadeSpan& span);
    // Words that start a declaration (uniform, texture, technique, …): recovery stops before them.
    static bool startsDeclaration(std::string_view word);
    // Skips to the end of a declaration: after the next ';' at this level, before a keyword that
    // starts a declaration, or before a '}' that closes an enclosing block.
    void recover();
    // Skips to the next `stop` at this nesting (not taking it), or before an unmatched '}'.
    void skipUntil(std::string_view stop);
    std::string readQualifiedName();

    // Symbols (qualified names) and their lookup through the enclosing namespaces.
    bool declare(const std::string& qualified, Symbol symbol, const std::string& element);
    // The symbol a name as written means here, looked for in this namespace and then each one
    // around it; of several with one name, the one of kind `want`.
    const Symbol* resolve(const std::string& written, std::optional<ReshadeDeclaration::Kind> want = std::nullopt) const;
    std::string qualify(const std::string& name) const { return namespace_ + name; }
    std::optional<ReshadeValue> constantNamed(const std::string& written) const;
    ReshadeNameLookup lookup() const {
        return [this](const std::string& name) { return constantNamed(name); };
    }
    // A state's or property's value: a name from `table` (any case), or a constant. Errors name the
    // state and list the table's names.
    std::optional<ReshadeValue> readStateValue(const ReshadeEnum* table, const std::string& state, const std::string& element);
    // Reads a texture name as written and resolves it: its qualified name, or nullopt after an error.
    std::optional<std::string> readTextureName(const std::string& element);
    void addDeclaration(ReshadeDeclaration::Kind kind, size_t index) { effect_.order.push_back({kind, index}); }

    // ReshadeFunctions.cpp
    void parseStruct();
    bool parseField(ReshadeField& field, const std::string& element, bool parameter);
    // `[name]` or `[name(constant, …)]`, any number, before a declaration.
    std::vector<ReshadeAttribute> parseAttributes();
    void parseFunction(const ReshadeType& returnType, const std::string& name, const SourceLocation& where,
                       std::vector<ReshadeAttribute> attributes);

    // ReshadeObjects.cpp
    void parseTexture(ReshadeType type, const std::string& name, const SourceLocation& where);
    void parseSampler(ReshadeType type, const std::string& name, const SourceLocation& where);
    void parseStorage(ReshadeType type, const std::string& name, const SourceLocation& where);
    // What samplers and storages share: before their properties, no array size, the annotations
    // and a '{' (false, an error said, when none follows); after them, a 'Texture' property and
    // the declaration.
    bool openBoundObject(ReshadeType& type, const std::string& kind, const SourceLocation& where, const std::string& element,
                         ReshadeAnnotations& annotations);
    template <class T>
    void declareBoundObject(std::vector<T>& list, T object, ReshadeDeclaration::Kind kind, bool hasTexture,
                            const std::string& element);
    // Reads `{ Name = value; … }`, calling `property` for each with the cursor at its value; it
    // reads the value and returns false after reporting an unknown property.
    template <class F>
    void parseProperties(const std::string& element, F property);

    // ReshadeTechniques.cpp
    void parseTechnique();
    void parsePass(ReshadePass& pass, const std::string& element);
    void parsePassState(ReshadePass& pass, const std::string& state, const SourceLocation& where, const std::string& element);

    ReshadeCursor c_;
    ReshadeEffect effect_;
    std::string namespace_;  // "" or "A::B::"
    std::map<std::string, std::vector<Symbol>> symbols_;
    std::map<std::string, std::vector<std::vector<std::string>>> overloads_;  // a function's parameter types, per overload
};

}  // namespace rmfx

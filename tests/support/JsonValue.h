#pragma once
// A strict reader of JSON text for tests that check files rmfx writes (no JSON library is a
// dependency): objects, arrays, strings with the common escapes, numbers, true/false/null.

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rmfx::test {

struct JsonValue {
    enum class Kind { Null, Bool, Number, String, Array, Object } kind = Kind::Null;
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<JsonValue> array;
    std::map<std::string, JsonValue> object;

    const JsonValue& operator[](const std::string& key) const {
        static const JsonValue missing;
        auto it = object.find(key);
        return it == object.end() ? missing : it->second;
    }
    bool has(const std::string& key) const { return object.count(key) > 0; }
};

class JsonReader {
public:
    // nullopt when the text is not exactly one JSON value (surrounding white space allowed).
    static std::optional<JsonValue> parse(const std::string& text) {
        JsonReader r(text);
        auto v = r.value();
        r.space();
        if (!v || r.at_ != text.size()) return std::nullopt;
        return v;
    }

private:
    explicit JsonReader(const std::string& text) : text_(text) {}

    void space() {
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    }
    bool take(char c) {
        space();
        if (at_ < text_.size() && text_[at_] == c) return ++at_, true;
        return false;
    }
    bool word(const char* w) {
        std::string s(w);
        if (text_.compare(at_, s.size(), s) != 0) return false;
        at_ += s.size();
        return true;
    }
    std::optional<std::string> stringText() {
        if (!take('"')) return std::nullopt;
        std::string out;
        while (at_ < text_.size() && text_[at_] != '"') {
            char c = text_[at_++];
            if (static_cast<unsigned char>(c) < 0x20) return std::nullopt;
            if (c != '\\') {
                out += c;
                continue;
            }
            if (at_ >= text_.size()) return std::nullopt;
            char e = text_[at_++];
            if (e == 'n') out += '\n';
            else if (e == 't') out += '\t';
            else if (e == '"' || e == '\\' || e == '/') out += e;
            else if (e == 'u' && at_ + 4 <= text_.size()) out += static_cast<char>(std::strtol(text_.substr(at_, 4).c_str(), nullptr, 16)), at_ += 4;
            else return std::nullopt;
        }
        if (at_ >= text_.size()) return std::nullopt;
        ++at_;
        return out;
    }
    std::optional<JsonValue> value() {
        space();
        if (at_ >= text_.size()) return std::nullopt;
        JsonValue v;
        char c = text_[at_];
        if (c == '{') {
            ++at_;
            v.kind = JsonValue::Kind::Object;
            if (take('}')) return v;
            do {
                auto key = stringText();
                if (!key || !take(':')) return std::nullopt;
                auto item = value();
                if (!item) return std::nullopt;
                v.object[*key] = std::move(*item);
            } while (take(','));
            if (!take('}')) return std::nullopt;
        } else if (c == '[') {
            ++at_;
            v.kind = JsonValue::Kind::Array;
            if (take(']')) return v;
            do {
                auto item = value();
                if (!item) return std::nullopt;
                v.array.push_back(std::move(*item));
            } while (take(','));
            if (!take(']')) return std::nullopt;
        } else if (c == '"') {
            auto s = stringText();
            if (!s) return std::nullopt;
            v.kind = JsonValue::Kind::String;
            v.string = *s;
        } else if (word("true") || word("false")) {
            v.kind = JsonValue::Kind::Bool;
            v.boolean = text_[at_ - 1] == 'e' && text_[at_ - 2] == 'u';
        } else if (word("null")) {
            v.kind = JsonValue::Kind::Null;
        } else {
            const char* begin = text_.c_str() + at_;
            char* end = nullptr;
            v.number = std::strtod(begin, &end);
            if (end == begin || !(c == '-' || std::isdigit(static_cast<unsigned char>(c))) || !std::isfinite(v.number))
                return std::nullopt;
            v.kind = JsonValue::Kind::Number;
            at_ += static_cast<size_t>(end - begin);
        }
        return v;
    }

    const std::string& text_;
    size_t at_ = 0;
};

}  // namespace rmfx::test

#include "io/media/ImageSequence.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace rmfx {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxDigits = 9;  // every 9-digit number fits an int

// One frame-number field as written in a pattern.
struct Field {
    std::string text;     // "%04d", "####"
    int digits = 0;
    std::string problem;  // why the field cannot be used; "" when it can
};

// A pattern's literal text around its fields: literals[i] comes before fields[i], and the last
// literal after the last field.
struct ScannedPattern {
    std::vector<std::string> literals{""};
    std::vector<Field> fields;
};

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

ScannedPattern scan(const std::string& pattern) {
    ScannedPattern scanned;
    size_t i = 0;
    while (i < pattern.size()) {
        const char c = pattern[i];
        if (c == '%' && i + 1 < pattern.size() && pattern[i + 1] == '%') {
            scanned.literals.back() += '%';
            i += 2;
            continue;
        }
        if (c == '%') {
            size_t j = i + 1;
            while (j < pattern.size() && isDigit(pattern[j])) ++j;
            if (j < pattern.size() && pattern[j] == 'd') {
                Field field;
                field.text = pattern.substr(i, j + 1 - i);
                const std::string width = pattern.substr(i + 1, j - i - 1);
                if (!width.empty() && width[0] != '0')
                    field.problem = field.text + " pads with spaces; use %0" + width + "d";
                else if (width.size() > 3 || (!width.empty() && std::stoi(width) > kMaxDigits))
                    field.problem = field.text + " pads to more than " + std::to_string(kMaxDigits) + " digits";
                else
                    field.digits = width.empty() ? 0 : std::stoi(width);
                scanned.fields.push_back(field);
                scanned.literals.emplace_back();
                i = j + 1;
                continue;
            }
        }
        if (c == '#') {
            size_t j = i;
            while (j < pattern.size() && pattern[j] == '#') ++j;
            Field field;
            field.text = pattern.substr(i, j - i);
            const int run = int(j - i);
            field.digits = run == 1 ? 4 : run;
            if (field.digits > kMaxDigits)
                field.problem = field.text + " pads to more than " + std::to_string(kMaxDigits) + " digits";
            scanned.fields.push_back(field);
            scanned.literals.emplace_back();
            i = j;
            continue;
        }
        scanned.literals.back() += c;
        ++i;
    }
    return scanned;
}

std::string padded(int frame, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%0*d", digits, frame);
    return text;
}

// The frame a file name's digits stand for, when the pattern writes exactly these digits for it.
std::optional<int> frameOf(const std::string& digitText, int digits) {
    if (digitText.empty() || digitText.size() > size_t(kMaxDigits) ||
        !std::all_of(digitText.begin(), digitText.end(), isDigit))
        return std::nullopt;
    const int frame = std::stoi(digitText);
    if (padded(frame, digits) != digitText) return std::nullopt;
    return frame;
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string FramePattern::fileName(int frame) const { return prefix + padded(frame, digits) + suffix; }

bool isSequencePattern(const std::string& pattern) { return !scan(pattern).fields.empty(); }

Result<FramePattern> parseFramePattern(const std::string& pattern) {
    const ScannedPattern scanned = scan(pattern);
    if (scanned.fields.empty())
        return Error{pattern + ": no frame-number field (%d, %04d or ####)"};
    if (scanned.fields.size() > 1) {
        std::string fields;
        for (const Field& field : scanned.fields) fields += (fields.empty() ? "" : ", ") + field.text;
        return Error{pattern + ": " + std::to_string(scanned.fields.size()) + " frame-number fields (" + fields +
                     "); a pattern has one"};
    }
    const Field& field = scanned.fields[0];
    if (!field.problem.empty()) return Error{pattern + ": " + field.problem};
    FramePattern parsed{scanned.literals[0], scanned.literals[1], field.digits};
    if (parsed.suffix.find('/') != std::string::npos)
        return Error{pattern + ": the frame number " + field.text + " is in a folder name; it must be in the file name"};
    return parsed;
}

std::string frameFileName(const std::string& pattern, int frame) {
    Result<FramePattern> parsed = parseFramePattern(pattern);
    return parsed ? parsed->fileName(frame) : pattern;
}

Result<std::vector<SequenceFrame>> findSequenceFrames(const std::string& pattern) {
    Result<FramePattern> parsed = parseFramePattern(pattern);
    if (!parsed) return Error{parsed.error()};
    const size_t slash = parsed->prefix.rfind('/');
    const std::string folderText = slash == std::string::npos ? "" : parsed->prefix.substr(0, slash + 1);
    const std::string namePrefix = slash == std::string::npos ? parsed->prefix : parsed->prefix.substr(slash + 1);
    const fs::path folder = folderText.empty() ? fs::path(".") : fs::path(folderText);
    const std::string folderName = folderText.empty() ? std::string("the current folder") : folder.string();

    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return Error{pattern + ": no folder " + folderName};
    std::vector<SequenceFrame> frames;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= namePrefix.size() + parsed->suffix.size() || !startsWith(name, namePrefix) ||
            !endsWith(name, parsed->suffix))
            continue;
        const std::string digitText =
            name.substr(namePrefix.size(), name.size() - namePrefix.size() - parsed->suffix.size());
        const std::optional<int> frame = frameOf(digitText, parsed->digits);
        std::error_code typeError;
        if (!frame || !fs::is_regular_file(it->path(), typeError)) continue;
        frames.push_back({*frame, fs::path(folderText + name)});
    }
    if (ec) return Error{pattern + ": cannot list " + folderName + ": " + ec.message()};
    if (frames.empty()) return Error{pattern + ": no file in " + folderName + " matches"};

    std::sort(frames.begin(), frames.end(), [](const SequenceFrame& a, const SequenceFrame& b) { return a.frame < b.frame; });
    const int firstFrame = frames.front().frame;
    const int lastFrame = frames.back().frame;
    const int64_t missing = int64_t(lastFrame) - firstFrame + 1 - int64_t(frames.size());
    if (missing > 0) {
        int firstMissing = firstFrame;
        for (const SequenceFrame& f : frames) {
            if (f.frame != firstMissing) break;
            ++firstMissing;
        }
        return Error{pattern + ": frames " + std::to_string(firstFrame) + " to " + std::to_string(lastFrame) +
                     " have gaps: " + parsed->fileName(firstMissing) + " is missing (" + std::to_string(missing) +
                     (missing == 1 ? " frame" : " frames") + " missing in all)"};
    }
    return frames;
}

Result<std::pair<int, int>> selectFrameRange(const std::vector<SequenceFrame>& frames, std::pair<int, int> numbers) {
    auto [first, last] = numbers;
    if (first > last)
        return Error{std::to_string(first) + "-" + std::to_string(last) + ": the first frame comes after the last"};
    if (frames.empty()) return Error{"the sequence has no frames"};
    const int shotFirst = frames.front().frame, shotLast = frames.back().frame;
    if (first < shotFirst || last > shotLast)
        return Error{std::to_string(first) + "-" + std::to_string(last) + " reaches outside the sequence, whose frames are " +
                     std::to_string(shotFirst) + "-" + std::to_string(shotLast)};
    auto index = [&](int number) {
        return static_cast<int>(std::lower_bound(frames.begin(), frames.end(), number,
                                                 [](const SequenceFrame& f, int n) { return f.frame < n; }) -
                                frames.begin());
    };
    return std::pair<int, int>(index(first), index(last));
}

}  // namespace rmfx

#include "validation/ImageInputs.h"

#include <cctype>
#include <map>
#include <memory>
#include <system_error>

#include "io/image/InputImage.h"

namespace rmfx {
namespace {

bool isIdentifier(const std::string& text) {
    if (text.empty() || !(std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_')) return false;
    for (char c : text)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return true;
}

std::string sizeText(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

}  // namespace

InputArgument parseInputArgument(const std::string& text) {
    InputArgument argument;
    argument.text = text;
    std::string rest = text;
    std::error_code ec;
    if (size_t equals = text.find('='); equals != std::string::npos && isIdentifier(text.substr(0, equals)) &&
                                        !std::filesystem::is_regular_file(text, ec)) {
        argument.name = text.substr(0, equals);
        rest = text.substr(equals + 1);
    }
    auto [file, layer] = splitLayerSuffix(rest);
    argument.file = file;
    argument.layer = layer;
    return argument;
}

Result<std::vector<const ImageInput*>> resolveInputArguments(const Workspace& ws, const std::vector<InputArgument>& inputs) {
    Diagnostics d;
    auto error = [&](const InputArgument& a, const std::string& message) {
        d.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "--input " + a.text, message});
    };
    std::string known;
    for (const ImageInput& input : ws.inputs) known += (known.empty() ? "'" : ", '") + input.name + "'";
    known = known.empty() ? "it declares no <input>" : "its inputs: " + known;
    std::vector<const ImageInput*> resolved;
    std::map<std::string, const InputArgument*> taken;
    for (const InputArgument& a : inputs) {
        const ImageInput* input = nullptr;
        if (a.name.empty() && ws.inputs.size() == 1) input = &ws.inputs.front();
        else if (a.name.empty()) {
            error(a, "name the input: --input NAME=FILE (" + known + ")");
            continue;
        } else if (!(input = ws.findInput(a.name))) {
            error(a, "the workspace has no input '" + a.name + "' (" + known + ")");
            continue;
        }
        if (auto [it, fresh] = taken.emplace(input->name, &a); !fresh) {
            error(a, "input '" + input->name + "' is already given by --input " + it->second->text);
            continue;
        }
        resolved.push_back(input);
    }
    if (hasErrors(d)) return Result<std::vector<const ImageInput*>>::failure(std::move(d));
    return resolved;
}

Result<SuppliedInputs> supplyInputs(Workspace& ws, const std::vector<InputArgument>& inputs,
                                    std::optional<glm::ivec2> size, int maxSide) {
    Result<std::vector<const ImageInput*>> resolved = resolveInputArguments(ws, inputs);
    if (!resolved) return Result<SuppliedInputs>::failure(std::move(resolved).diagnostics());
    Diagnostics d;
    auto error = [&](const InputArgument& a, const std::string& message) {
        d.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "--input " + a.text, message});
    };

    // Which input each argument fills, and its image.
    struct Read {
        const ImageInput* input;
        const InputArgument* argument;
        Image image;
    };
    std::vector<Read> read;
    for (size_t k = 0; k < inputs.size(); ++k) {
        const InputArgument& a = inputs[k];
        const ImageInput* input = (*resolved)[k];
        if (a.image) {
            if (a.image->channels != 4 || a.image->width <= 0 || a.image->height <= 0 ||
                a.image->pixels.size() != size_t(a.image->width) * size_t(a.image->height) * 4u)
                error(a, "an image given in memory must be RGBA with at least one pixel");
            else if (a.image->width > maxSide || a.image->height > maxSide)
                error(a, sizeText({a.image->width, a.image->height}) + " is larger than " + std::to_string(maxSide) +
                             " pixels on a side");
            else
                read.push_back({input, &a, *a.image});
            continue;
        }
        Result<InputImage> image = readInputImage(a.file, a.layer, maxSide);
        if (!image) {
            error(a, image.error());
            continue;
        }
        for (const std::string& note : image->notes)
            d.push_back({Diagnostic::Severity::Warning, {ws.path.string(), 0}, "--input " + a.text, note});
        read.push_back({input, &a, std::move(image->image)});
    }
    if (hasErrors(d)) return Result<SuppliedInputs>::failure(std::move(d));

    SuppliedInputs supplied;
    supplied.viewport = glm::ivec2(ws.width, ws.height);
    if (size) {
        supplied.viewport = *size;
    } else {
        for (const Read& r : read)
            if (r.input->sizesViewport) {
                supplied.viewport = {r.image.width, r.image.height};
                break;
            }
    }
    for (Read& r : read) {
        const glm::ivec2 own(r.image.width, r.image.height);
        if (r.input->sizesViewport && own != supplied.viewport) {
            Result<Image> resampled = resampleImage(r.image, supplied.viewport.x, supplied.viewport.y);
            if (!resampled) {
                error(*r.argument, r.argument->file.string() + ": " + resampled.error());
                continue;
            }
            d.push_back({Diagnostic::Severity::Warning, {ws.path.string(), 0}, "--input " + r.argument->text,
                         r.argument->file.string() + ": resampled from " + sizeText(own) + " to " +
                             sizeText(supplied.viewport) + " (triangle filter), the size the workspace renders at"});
            r.image = std::move(*resampled);
        }
        ws.findTexture(r.input->name)->supplied = std::make_shared<const Image>(std::move(r.image));
        supplied.given.insert(r.input->name);
    }
    if (hasErrors(d)) return Result<SuppliedInputs>::failure(std::move(d));
    return {std::move(supplied), std::move(d)};
}

}  // namespace rmfx

#include "io/image/InputImage.h"
#include "io/image/codecs/CodecFunctions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "io/image/ImageFileError.h"
#include "io/image/ImageMemoryLimit.h"
#include "io/image/ImageIO.h"

namespace rmfx::codecs {

namespace fs = std::filesystem;

namespace {

// A layer: the channels of one part that share a name prefix ("ViewLayer.Combined" for
// "ViewLayer.Combined.R"); the plain channels (R, G, B, A, Y, Z…) form the layer with no prefix.
struct Layer {
    int part = 0;
    std::string name;    // as the user names it (see layerName)
    std::string prefix;  // "" for the plain channels
    std::vector<int> channels;           // indices into the part's channels, in file order
    std::vector<std::string> shortNames;  // the channels' names without the prefix
};

struct Part {
    std::string name;  // "" when the file names none
    OIIO::ImageSpec spec;
    std::vector<Layer> layers;
};

// Which of a layer's channels become R, G, B and A (-1: none), as indices into Layer::channels.
struct ChannelMapping {
    int red = -1, green = -1, blue = -1, alpha = -1;
    std::string note;  // how the channels were interpreted, when that is not plain RGB(A)
};

std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ") {
    std::string text;
    for (const std::string& item : items) {
        if (!text.empty()) text += separator;
        text += item;
    }
    return text;
}

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool isFloatType(OIIO::TypeDesc type) {
    return type.basetype == OIIO::TypeDesc::HALF || type.basetype == OIIO::TypeDesc::FLOAT ||
           type.basetype == OIIO::TypeDesc::DOUBLE;
}

// A multi-part file's parts often repeat their name as the channels' prefix (part "diffuse",
// channels "diffuse.R"); the layer is then called by that name once.
std::string layerName(const std::string& part, const std::string& prefix) {
    if (part.empty()) return prefix;
    if (prefix.empty()) return part;
    if (prefix == part || prefix.rfind(part + ".", 0) == 0) return prefix;
    return part + "." + prefix;
}

std::vector<Layer> layersOf(int partIndex, const std::string& partName, const OIIO::ImageSpec& spec) {
    std::vector<Layer> layers;
    for (int c = 0; c < spec.nchannels; ++c) {
        const std::string& channel = spec.channelnames[size_t(c)];
        const size_t dot = channel.rfind('.');
        const std::string prefix = dot == std::string::npos ? "" : channel.substr(0, dot);
        const std::string shortName = dot == std::string::npos ? channel : channel.substr(dot + 1);
        auto it = std::find_if(layers.begin(), layers.end(), [&](const Layer& l) { return l.prefix == prefix; });
        if (it == layers.end()) {
            layers.push_back({partIndex, layerName(partName, prefix), prefix, {}, {}});
            it = layers.end() - 1;
        }
        it->channels.push_back(c);
        it->shortNames.push_back(shortName);
    }
    return layers;
}

int find(const std::vector<std::string>& names, std::initializer_list<const char*> wanted) {
    for (const char* w : wanted) {
        auto it = std::find(names.begin(), names.end(), w);
        if (it != names.end()) return int(it - names.begin());
    }
    return -1;
}

bool hasRgb(const Layer& layer) {
    return find(layer.shortNames, {"R", "r"}) >= 0 && find(layer.shortNames, {"G", "g"}) >= 0 &&
           find(layer.shortNames, {"B", "b"}) >= 0;
}

ChannelMapping mapChannels(const Layer& layer) {
    ChannelMapping m;
    const std::vector<std::string>& names = layer.shortNames;
    m.alpha = find(names, {"A", "a"});
    if (hasRgb(layer)) {
        m.red = find(names, {"R", "r"});
        m.green = find(names, {"G", "g"});
        m.blue = find(names, {"B", "b"});
        return m;
    }
    const int count = int(names.size());
    if (count == 1) {
        m.red = m.green = m.blue = 0;
        m.alpha = -1;
        m.note = "1 channel (" + names[0] + "): read as grey, alpha 1";
    } else if (count == 2) {
        if (m.alpha < 0) m.alpha = 1;
        m.red = m.green = m.blue = 1 - m.alpha;
        m.note = "2 channels (" + names[size_t(m.red)] + ", " + names[size_t(m.alpha)] + "): read as grey and alpha";
    } else {
        std::vector<int> colour;
        for (int i = 0; i < count && colour.size() < 3; ++i)
            if (i != m.alpha) colour.push_back(i);
        m.red = colour[0];
        m.green = colour[1];
        m.blue = colour.size() > 2 ? colour[2] : colour[1];
        m.note = "channels " + names[size_t(m.red)] + ", " + names[size_t(m.green)] + ", " +
                 names[size_t(m.blue)] + " read as R, G, B";
    }
    return m;
}

std::string channelList(const Layer& layer) { return joined(layer.shortNames, ","); }

std::string displayName(const Layer& layer) { return layer.name.empty() ? "(unnamed)" : layer.name; }

// "layers: ViewLayer.Combined (R,G,B,A), ViewLayer.Depth (Z); parts: beauty, depth"
std::string describeContents(const std::vector<Part>& parts) {
    std::vector<std::string> layers;
    std::vector<std::string> partNames;
    for (const Part& part : parts) {
        for (const Layer& layer : part.layers)
            layers.push_back(displayName(layer) + " (" + channelList(layer) + ")");
        if (parts.size() > 1) partNames.push_back(part.name.empty() ? "(unnamed)" : part.name);
    }
    std::string text = "layers: " + joined(layers);
    if (!partNames.empty()) text += "; parts: " + joined(partNames);
    return text;
}

std::vector<const Layer*> layersIn(const std::vector<Part>& parts, std::optional<int> onlyPart) {
    std::vector<const Layer*> layers;
    for (size_t p = 0; p < parts.size(); ++p)
        if (!onlyPart || *onlyPart == int(p))
            for (const Layer& layer : parts[p].layers) layers.push_back(&layer);
    return layers;
}

// The layer read when the user names none (or names a part): see readInputImage.
Result<const Layer*> defaultLayer(const fs::path& file, const std::vector<Part>& parts, std::optional<int> onlyPart) {
    const std::vector<const Layer*> layers = layersIn(parts, onlyPart);
    for (const Layer* layer : layers)
        if (layer->prefix.empty() && hasRgb(*layer)) return layer;
    for (const Layer* layer : layers)
        if (layer->prefix == "Combined" || endsWith(layer->prefix, ".Combined")) return layer;
    if (layers.size() == 1) return layers[0];
    const std::string where = onlyPart ? "part '" + parts[size_t(*onlyPart)].name + "'" : std::string("the file");
    return imageFileError(file, where + " has several layers and none is plain R,G,B or named Combined; "
                                "choose one with FILE:layer; " + describeContents(parts));
}

Result<const Layer*> chosenLayer(const fs::path& file, const std::vector<Part>& parts, const std::string& choice) {
    if (choice.empty()) return defaultLayer(file, parts, std::nullopt);
    for (size_t p = 0; p < parts.size(); ++p)
        if (!parts[p].name.empty() && parts[p].name == choice) return defaultLayer(file, parts, int(p));
    const std::vector<const Layer*> layers = layersIn(parts, std::nullopt);
    for (const Layer* layer : layers)
        if (layer->name == choice || (!layer->prefix.empty() && layer->prefix == choice)) return layer;
    std::vector<const Layer*> byEnding;
    for (const Layer* layer : layers)
        if (endsWith(layer->name, "." + choice)) byEnding.push_back(layer);
    if (byEnding.size() == 1) return byEnding[0];
    if (byEnding.size() > 1) {
        std::vector<std::string> names;
        for (const Layer* layer : byEnding) names.push_back(layer->name);
        return imageFileError(file, "layer name '" + choice + "' is ambiguous: it matches " + joined(names));
    }
    return imageFileError(file, "no layer or part named '" + choice + "'; " + describeContents(parts));
}

std::string plural(int64_t count, const std::string& one, const std::string& many) {
    return std::to_string(count) + " " + (count == 1 ? one : many);
}

// One note counting the pixels that hold NaN, infinite or negative values, or "" when none do.
std::string unusualValuesNote(const Image& image) {
    int64_t nan = 0, inf = 0, negative = 0;
    const size_t count = size_t(image.width) * size_t(image.height);
    for (size_t i = 0; i < count; ++i) {
        bool hasNan = false, hasInf = false, hasNegative = false;
        for (int c = 0; c < 4; ++c) {
            const float v = image.pixels[i * 4 + size_t(c)];
            hasNan |= std::isnan(v);
            hasInf |= std::isinf(v);
            hasNegative |= std::isfinite(v) && v < 0.0f;
        }
        nan += hasNan;
        inf += hasInf;
        negative += hasNegative;
    }
    std::vector<std::string> parts;
    if (nan) parts.push_back(plural(nan, "pixel holds NaN", "pixels hold NaN"));
    if (inf) parts.push_back(plural(inf, "pixel holds an infinite value", "pixels hold infinite values"));
    if (negative) parts.push_back(plural(negative, "pixel holds a negative value", "pixels hold negative values"));
    if (parts.empty()) return "";
    return joined(parts) + " (kept as they are; effects sanitise their inputs)";
}

struct ReadChannels {
    std::vector<float> samples;  // last - first + 1 per pixel
    int bits = 32;               // of the widest channel read
    bool integer = false;        // some channel held integer data: decoded from sRGB
};

template <class Int>
bool readIntegers(OIIO::ImageInput& in, int part, int first, int last, size_t pixels, int keepLinear,
                  std::vector<float>& out) {
    const int stride = last - first + 1;
    std::vector<Int> raw(pixels * size_t(stride));
    if (!in.read_image(part, 0, first, last + 1, OIIO::BaseTypeFromC<Int>::value, raw.data())) return false;
    const size_t levels = size_t(std::numeric_limits<Int>::max()) + 1;
    std::vector<float> decoded(levels), linear(levels);
    // Exact value / max before decoding (OpenImageIO's own conversion multiplies by a rounded reciprocal).
    for (size_t v = 0; v < levels; ++v) {
        linear[v] = float(v) / float(levels - 1);
        decoded[v] = srgbDecode(linear[v]);
    }
    out.resize(raw.size());
    for (size_t i = 0; i < raw.size(); ++i)
        out[i] = (int(i % size_t(stride)) + first == keepLinear ? linear : decoded)[raw[i]];
    return true;
}

// Reads channels [first, last] of a part as float samples. Integer data is decoded from sRGB here,
// except the channel at `keepLinear` (alpha).
Result<ReadChannels> readChannels(const fs::path& file, OIIO::ImageInput& in, const Part& part, int partIndex,
                                  int first, int last, int keepLinear) {
    const OIIO::ImageSpec& spec = part.spec;
    const size_t pixels = size_t(spec.width) * size_t(spec.height);
    ReadChannels read;
    int bits = 0;
    bool allFloat = true, allUint8 = true, allUint16 = true;
    for (int c = first; c <= last; ++c) {
        const OIIO::TypeDesc type = spec.channelformat(c);
        allFloat &= isFloatType(type);
        allUint8 &= type.basetype == OIIO::TypeDesc::UINT8;
        allUint16 &= type.basetype == OIIO::TypeDesc::UINT16;
        bits = std::max(bits, int(type.size() * 8));
    }
    read.integer = !allFloat;
    read.bits = bits;
    bool ok;
    if (allUint8) {
        ok = readIntegers<uint8_t>(in, partIndex, first, last, pixels, keepLinear, read.samples);
    } else if (allUint16) {
        ok = readIntegers<uint16_t>(in, partIndex, first, last, pixels, keepLinear, read.samples);
    } else {
        read.samples.resize(pixels * size_t(last - first + 1));
        ok = in.read_image(partIndex, 0, first, last + 1, OIIO::TypeDesc::FLOAT, read.samples.data());
        if (ok && read.integer) {
            const int stride = last - first + 1;
            for (size_t i = 0; i < read.samples.size(); ++i)
                if (int(i % size_t(stride)) + first != keepLinear) read.samples[i] = srgbDecode(read.samples[i]);
        }
    }
    if (!ok) return imageFileError(file, "cannot read pixels: " + oneLine(in.geterror()));
    return read;
}

Result<std::vector<Part>> readParts(const fs::path& file, OIIO::ImageInput& in) {
    std::vector<Part> parts;
    for (int p = 0; in.seek_subimage(p, 0); ++p) {
        Part part;
        part.spec = in.spec();
        part.name = part.spec.get_string_attribute("oiio:subimagename");
        part.layers = layersOf(p, part.name, part.spec);
        parts.push_back(std::move(part));
    }
    in.geterror();  // seeking past the last part leaves an error that says nothing about the file
    if (parts.empty()) return imageFileError(file, "the file holds no image");
    return parts;
}

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

Result<void> checkSize(const fs::path& file, const OIIO::ImageSpec& spec, int maxSide) {
    if (spec.deep) return imageFileError(file, "deep images are not supported");
    if (spec.depth > 1) return imageFileError(file, "volume images are not supported");
    if (spec.width <= 0 || spec.height <= 0)
        return imageFileError(file, "image has no pixels (" + sizeText(spec.width, spec.height) + ")");
    const int width = std::max(spec.width, spec.full_width);
    const int height = std::max(spec.height, spec.full_height);
    if (width > maxSide || height > maxSide)
        return imageFileError(file, "image is " + sizeText(width, height) + ", larger than the limit of " +
                                    std::to_string(maxSide) + " pixels a side");
    return {};
}

bool dataWindowIsDisplayWindow(const OIIO::ImageSpec& spec) {
    return spec.full_width <= 0 || spec.full_height <= 0 ||
           (spec.x == spec.full_x && spec.y == spec.full_y && spec.width == spec.full_width &&
            spec.height == spec.full_height);
}

}  // namespace

Result<InputImage> readInputImage(const fs::path& file, const std::string& layerChoice, int maxSide) {
    std::error_code ec;
    if (!fs::exists(file, ec)) return imageFileError(file, "no such file");
    if (!fs::is_regular_file(file, ec)) return imageFileError(file, "not a regular file");

    // Without this hint OpenImageIO premultiplies PNG/TGA colour by alpha on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(file.string(), &config);
    if (!in) return imageFileError(file, "cannot read image: " + oneLine(OIIO::geterror()));

    Result<std::vector<Part>> parts = readParts(file, *in);
    if (!parts) return Error{parts.error()};
    Result<const Layer*> chosen = chosenLayer(file, *parts, layerChoice);
    if (!chosen) return Error{chosen.error()};
    const Layer& layer = **chosen;
    const Part& part = (*parts)[size_t(layer.part)];
    const OIIO::ImageSpec& spec = part.spec;
    if (Result<void> size = checkSize(file, spec, maxSide); !size) return Error{size.error()};
    // Held as RGBA float, whatever the file stores.
    if (Result<void> memory = checkImageMemory(file, std::max(spec.width, spec.full_width),
                                               std::max(spec.height, spec.full_height), 1, 4);
        !memory)
        return Error{memory.error()};

    InputImage input;
    input.layer = layer.name;
    const std::string prefix = file.string() + ": ";
    const std::vector<const Layer*> allLayers = layersIn(*parts, std::nullopt);
    if (layerChoice.empty() && allLayers.size() > 1) {
        std::vector<std::string> others;
        for (const Layer* other : allLayers)
            if (other != &layer) others.push_back(displayName(*other));
        input.notes.push_back(prefix + "read layer '" + displayName(layer) + "'; the file also has " + joined(others) +
                              " (choose one with FILE:layer)");
    }

    const ChannelMapping mapping = mapChannels(layer);
    if (!mapping.note.empty()) input.notes.push_back(prefix + mapping.note);
    const int channelOf[4] = {layer.channels[size_t(mapping.red)], layer.channels[size_t(mapping.green)],
                              layer.channels[size_t(mapping.blue)],
                              mapping.alpha >= 0 ? layer.channels[size_t(mapping.alpha)] : -1};
    const int first = std::min({channelOf[0], channelOf[1], channelOf[2], channelOf[3] >= 0 ? channelOf[3] : channelOf[0]});
    const int last = std::max({channelOf[0], channelOf[1], channelOf[2], channelOf[3]});
    Result<ReadChannels> read = readChannels(file, *in, part, layer.part, first, last, channelOf[3]);
    if (!read) return Error{read.error()};
    in->close();
    if (read->integer)
        input.notes.push_back(prefix + std::to_string(read->bits) + "-bit sRGB: decoded to linear");

    // The image covers the display window; pixels of the data window outside it are dropped and
    // parts of it the data window does not cover are transparent black.
    const bool sameWindow = dataWindowIsDisplayWindow(spec);
    const int originX = sameWindow ? spec.x : spec.full_x;
    const int originY = sameWindow ? spec.y : spec.full_y;
    Image& image = input.image;
    image.width = sameWindow ? spec.width : spec.full_width;
    image.height = sameWindow ? spec.height : spec.full_height;
    image.channels = 4;
    image.highDynamicRange = !read->integer;
    image.bitsPerChannel = read->bits;
    image.pixels.assign(size_t(image.width) * size_t(image.height) * 4, 0.0f);
    if (!sameWindow)
        input.notes.push_back(prefix + "data window " + sizeText(spec.width, spec.height) + " at (" +
                              std::to_string(spec.x) + ", " + std::to_string(spec.y) + ") differs from display window " +
                              sizeText(spec.full_width, spec.full_height) + " at (" + std::to_string(spec.full_x) +
                              ", " + std::to_string(spec.full_y) + "): read within the display window, transparent black elsewhere");

    const int stride = last - first + 1;
    for (int y = 0; y < spec.height; ++y) {
        const int iy = spec.y + y - originY;
        if (iy < 0 || iy >= image.height) continue;
        for (int x = 0; x < spec.width; ++x) {
            const int ix = spec.x + x - originX;
            if (ix < 0 || ix >= image.width) continue;
            const float* source = &read->samples[(size_t(y) * size_t(spec.width) + size_t(x)) * size_t(stride)];
            for (int c = 0; c < 4; ++c)
                image.at(ix, iy, c) = channelOf[c] >= 0 ? source[channelOf[c] - first] : 1.0f;
        }
    }
    if (std::string note = unusualValuesNote(image); !note.empty()) input.notes.push_back(prefix + note);
    return input;
}

Result<Image> resampleImage(const Image& image, int width, int height) {
    if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
        image.pixels.size() != size_t(image.width) * size_t(image.height) * size_t(image.channels))
        return Error{"cannot resample an image of " + sizeText(image.width, image.height) + " with " +
                     std::to_string(image.channels) + " channels and " + std::to_string(image.pixels.size()) + " samples"};
    if (width <= 0 || height <= 0 || width > kMaxInputSide || height > kMaxInputSide)
        return Error{"cannot resample to " + sizeText(width, height) + " (1 to " + std::to_string(kMaxInputSide) +
                     " pixels a side)"};
    if (width == image.width && height == image.height) return image;

    const OIIO::ImageSpec sourceSpec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
    // resize only reads its source: wrapping the caller's pixels saves a copy of a large image.
    const OIIO::ImageBuf source(sourceSpec, const_cast<float*>(image.pixels.data()));
    OIIO::ImageBuf resized(OIIO::ImageSpec(width, height, image.channels, OIIO::TypeDesc::FLOAT));
    if (!OIIO::ImageBufAlgo::resize(resized, source, "triangle"))
        return Error{"cannot resample to " + sizeText(width, height) + ": " + oneLine(resized.geterror())};

    Image out = image;
    out.width = width;
    out.height = height;
    out.pixels.resize(size_t(width) * size_t(height) * size_t(image.channels));
    if (!resized.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out.pixels.data()))
        return Error{"cannot resample to " + sizeText(width, height) + ": " + oneLine(resized.geterror())};
    return out;
}

}  // namespace rmfx::codecs

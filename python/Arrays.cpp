#include "python/Arrays.h"

#include <array>
#include <cstdint>
#include <cstring>

#include "io/image/ImageIO.h"
#include "python/Errors.h"

namespace py = pybind11;

namespace rmfx::python {

namespace {

float halfToFloat(std::uint16_t h) {
    const std::uint32_t sign = std::uint32_t(h & 0x8000u) << 16;
    std::uint32_t exponent = (h >> 10) & 0x1fu;
    std::uint32_t mantissa = h & 0x3ffu;
    std::uint32_t bits;
    if (exponent == 0x1f) {
        bits = sign | 0x7f800000u | (mantissa << 13);  // infinity, NaN
    } else if (exponent != 0) {
        bits = sign | ((exponent + 112u) << 23) | (mantissa << 13);
    } else if (mantissa == 0) {
        bits = sign;  // ±0
    } else {  // subnormal: normalise
        exponent = 113;
        while (!(mantissa & 0x400u)) {
            mantissa <<= 1;
            --exponent;
        }
        bits = sign | (exponent << 23) | ((mantissa & 0x3ffu) << 13);
    }
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

// sRGB byte → linear, as readInputImage decodes an 8-bit file: the byte / 255, then srgbDecode.
const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int v = 0; v < 256; ++v) t[size_t(v)] = srgbDecode(float(v) / 255.0f);
        return t;
    }();
    return table;
}

std::string describe(const py::array& a) {
    std::string shape;
    for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
    if (a.ndim() == 1) shape += ",";
    return "an array of shape (" + shape + ") and dtype " + py::str(a.dtype()).cast<std::string>();
}

}  // namespace

Image imageFromArray(const py::handle& object, const std::string& what) {
    const std::string expected = "expected an array of shape (height, width, 3 or 4) of float32, float16 or uint8 (sRGB)";
    if (!py::isinstance<py::array>(object))
        fail(what + ": " + expected + ", or a path; got " + py::str(object.get_type().attr("__name__")).cast<std::string>(), what);
    py::array given = py::reinterpret_borrow<py::array>(object);
    const py::dtype dtype = given.dtype();
    const bool f32 = dtype.equal(py::dtype::of<float>());
    const bool f16 = dtype.equal(py::dtype("float16"));
    const bool u8 = dtype.equal(py::dtype::of<std::uint8_t>());
    if (!(f32 || f16 || u8) || given.ndim() != 3 || (given.shape(2) != 3 && given.shape(2) != 4) || given.shape(0) < 1 ||
        given.shape(1) < 1)
        fail(what + ": " + expected + "; got " + describe(given), what);
    if (given.shape(0) > 16384 || given.shape(1) > 16384)
        fail(what + ": at most 16384 pixels on a side; got " + describe(given), what);
    // C order, whatever strides the caller's array has (a view, a flipped image); no copy when it is already.
    py::array a = py::array::ensure(given, py::array::c_style);
    if (!a) throw py::error_already_set();
    Image image;
    image.height = int(a.shape(0));
    image.width = int(a.shape(1));
    image.channels = 4;
    image.highDynamicRange = !u8;
    image.bitsPerChannel = u8 ? 8 : f16 ? 16 : 32;
    const int channels = int(a.shape(2));
    const size_t pixels = size_t(image.width) * size_t(image.height);
    image.pixels.resize(pixels * 4);
    const std::array<float, 256>& srgb = srgbTable();
    for (size_t p = 0; p < pixels; ++p) {
        for (int c = 0; c < 4; ++c) {
            float v = 1.0f;
            if (c < channels) {
                const size_t i = p * size_t(channels) + size_t(c);
                if (f32) v = static_cast<const float*>(a.data())[i];
                else if (f16) v = halfToFloat(static_cast<const std::uint16_t*>(a.data())[i]);
                else {
                    const std::uint8_t byte = static_cast<const std::uint8_t*>(a.data())[i];
                    v = c < 3 ? srgb[byte] : float(byte) / 255.0f;
                }
            }
            image.pixels[p * 4 + size_t(c)] = v;
        }
    }
    return image;
}

std::optional<GlExecutor::InputPixels> directPixels(const py::handle& object) {
    if (!py::isinstance<py::array>(object)) return std::nullopt;
    py::array a = py::reinterpret_borrow<py::array>(object);
    const bool f32 = a.dtype().equal(py::dtype::of<float>()), f16 = a.dtype().equal(py::dtype("float16"));
    if (!(f32 || f16) || a.ndim() != 3 || a.shape(2) != 4 || a.shape(0) < 1 || a.shape(1) < 1 || a.shape(0) > 16384 ||
        a.shape(1) > 16384)
        return std::nullopt;
    const py::ssize_t item = f32 ? 4 : 2;
    if (a.strides(2) != item || (a.shape(1) > 1 && a.strides(1) != 4 * item) || a.strides(0) < a.shape(1) * 4 * item)
        return std::nullopt;
    GlExecutor::InputPixels pixels;
    pixels.data = a.data();
    pixels.width = int(a.shape(1));
    pixels.height = int(a.shape(0));
    pixels.half = f16;
    pixels.rowBytes = std::size_t(a.strides(0));
    return pixels;
}

py::array_t<float> arrayFromImage(const Image& image) {
    py::array_t<float> array({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(image.channels)});
    std::memcpy(array.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(float));
    return array;
}

py::array_t<float> arrayFromImage(Image&& image) {
    // The array owns the image's pixels: no copy.
    auto* pixels = new std::vector<float>(std::move(image.pixels));
    py::capsule owner(pixels, [](void* p) { delete static_cast<std::vector<float>*>(p); });
    return py::array_t<float>({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(image.channels)},
                              pixels->data(), owner);
}

py::array targetArray(const Image& image, TargetFormat format) {
    py::array_t<float> floats = arrayFromImage(image);
    py::module_ np = py::module_::import("numpy");
    auto normalised = [&](double largest, const char* type) {
        return py::array(np.attr("rint")(np.attr("multiply")(floats, largest)).attr("astype")(type));
    };
    switch (format) {
        case TargetFormat::RGBA8:
        case TargetFormat::R8:
        case TargetFormat::RG8: return normalised(255.0, "uint8");
        case TargetFormat::RGBA16:
        case TargetFormat::RG16: return normalised(65535.0, "uint16");
        case TargetFormat::RGBA16F:
        case TargetFormat::R16F:
        case TargetFormat::RG16F: return py::array(floats.attr("astype")("float16"));
        case TargetFormat::RGBA32F:
        case TargetFormat::R32F:
        case TargetFormat::RG32F:
        case TargetFormat::R11G11B10F:
        case TargetFormat::RGB10A2: break;
    }
    return floats;
}

}  // namespace rmfx::python

#include "frontend/rfx/detail/RfxMatrixOrder.h"

#include <charconv>
#include <string_view>

namespace rmfx::rfx {

HlslMatrixOrder hlslMatrixOrderOf(const RfxElement& workspace) {
    const std::optional<std::string> version = workspace.text("XML_VERSION", false);
    const std::string_view prefix = "RenderMonkey ";
    if (version && version->rfind(prefix, 0) == 0) {
        const char* first = version->data() + prefix.size();
        const char* last = version->data() + version->size();
        int major = 0, minor = 0;
        auto [afterMajor, majorError] = std::from_chars(first, last, major);
        if (majorError == std::errc() && afterMajor < last && *afterMajor == '.') {
            // "1.71" is 1.71, so only the first digit after the point orders minor versions.
            const char* digit = afterMajor + 1;
            if (digit < last && *digit >= '0' && *digit <= '9') {
                minor = *digit - '0';
                return major < 1 || (major == 1 && minor < 6) ? HlslMatrixOrder::ColumnVector : HlslMatrixOrder::RowVector;
            }
        }
    }
    workspace.warning("XML_VERSION " + (version ? "\"" + *version + "\"" : std::string("missing")) +
                      ": HLSL semantic matrices are passed as RenderMonkey 1.6 and later did, for mul(v, M)");
    return HlslMatrixOrder::RowVector;
}

}  // namespace rmfx::rfx

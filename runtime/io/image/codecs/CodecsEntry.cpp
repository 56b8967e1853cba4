// The module's one exported symbol (io/image/ImageCodecs.h); everything else in it is hidden.
#include <atomic>

#include "io/image/ImageCodecs.h"
#include "io/image/ImageMemoryLimit.h"
#include "io/image/codecs/CodecFunctions.h"

namespace rmfx {
namespace {
std::atomic<std::uint64_t (*)()> hostLimit{nullptr};
}  // namespace

// The module's image memory limit is the host's (the module holds no copy of the setting).
std::uint64_t imageMemoryLimit() {
    std::uint64_t (*host)() = hostLimit.load();
    return host ? host() : kDefaultImageMemoryLimit;
}

namespace codecs {
void useHostImageMemoryLimit(std::uint64_t (*hostImageMemoryLimit)()) { hostLimit.store(hostImageMemoryLimit); }
}  // namespace codecs

}  // namespace rmfx

extern "C" __attribute__((visibility("default"))) const rmfx::ImageCodecs* rmfx_image_codecs_v1(
    std::uint64_t (*hostImageMemoryLimit)()) {
    using namespace rmfx;
    codecs::useHostImageMemoryLimit(hostImageMemoryLimit);
    static const ImageCodecs table = [] {
        ImageCodecs t;
        t.readImage = codecs::readImage;
        t.readVolumeImage = codecs::readVolumeImage;
        t.writeImage = codecs::writeImage;
        t.readInputImage = codecs::readInputImage;
        t.resampleImage = codecs::resampleImage;
        t.compareImages = codecs::compareImages;
        t.checkImageFileMemory = codecs::checkImageFileMemory;
        t.readDdsCubeMap = codecs::readDdsCubeMap;
        return t;
    }();
    return &table;
}

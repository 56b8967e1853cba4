#include "io/image/ImageCodecs.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <future>
#include <memory>
#include <mutex>
#include <system_error>
#include <utility>

#include "core/InstallLayout.h"
#include "core/LibraryLoading.h"
#include "io/image/DdsCubeMap.h"
#include "io/image/ImageMemoryLimit.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;

// Where to look: $RMFX_IMAGE_CODECS alone when set; else beside the program or shared library
// that holds this code (librmfx.so), in the lib folder of the package installed around it (an
// installed rmfx program or Python module: core/InstallLayout.h), then where this build put it.
std::vector<fs::path> candidates() {
    if (const char* chosen = std::getenv("RMFX_IMAGE_CODECS"); chosen && *chosen) return {fs::path(chosen)};
    std::vector<fs::path> paths;
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&startLoadingImageCodecs), &info) && info.dli_fname) {
        std::error_code error;
        fs::path holder = fs::canonical(info.dli_fname, error);
        if (!error) {
            paths.push_back(holder.parent_path() / kImageCodecsFileName);
            paths.push_back(holder.parent_path().parent_path() / "lib" / "rmfx" / kImageCodecsFileName);
        }
    }
    if (auto installed = installedFile(InstallFolder::Lib, kImageCodecsFileName);
        installed && std::find(paths.begin(), paths.end(), *installed) == paths.end())
        paths.push_back(*installed);
    paths.push_back(fs::path(RMFX_IMAGE_CODECS_BUILD_PATH));
    return paths;
}

// `marker` marks the load under way from before its thread starts to the end of dlopen.
Result<const ImageCodecs*> load(std::unique_ptr<LibraryLoadingScope> marker, std::function<void()> first) {
    if (first) first();
    const std::vector<fs::path> paths = candidates();
    std::string tried;
    for (const fs::path& path : paths) {
        std::error_code error;
        if (paths.size() > 1 && !fs::is_regular_file(path, error)) {
            tried += (tried.empty() ? "" : ", ") + ("'" + path.string() + "'");
            continue;
        }
        void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        marker.reset();
        if (!module) return Error{"cannot load rmfx's image codecs '" + path.string() + "': " + dlerror()};
        auto entry = reinterpret_cast<ImageCodecsEntry>(dlsym(module, kImageCodecsEntry));
        const ImageCodecs* table = entry ? entry(&imageMemoryLimit) : nullptr;
        if (!table || table->version != kImageCodecsVersion || table->size != sizeof(ImageCodecs))
            return Error{"'" + path.string() + "' is not this build's image codecs module (" + kImageCodecsEntry +
                         " missing or of another version): rebuild rmfx"};
        return table;
    }
    return Error{"cannot find rmfx's image codecs (" + std::string(kImageCodecsFileName) + ", which reads and writes images): not at " +
                 tried + "; set RMFX_IMAGE_CODECS to its path"};
}

std::mutex loadingMutex;
std::shared_future<Result<const ImageCodecs*>> loading;

// The load, started on its first call.
std::shared_future<Result<const ImageCodecs*>> loadingStarted(std::function<void()> first) {
    std::lock_guard<std::mutex> lock(loadingMutex);
    if (!loading.valid())
        loading = std::async(std::launch::async, load, std::make_unique<LibraryLoadingScope>(), std::move(first)).share();
    return loading;
}

}  // namespace

void startLoadingImageCodecs(std::function<void()> first) { loadingStarted(std::move(first)); }

// The shared state lives as long as `loading` does, so the reference stays good.
const Result<const ImageCodecs*>& imageCodecs() { return loadingStarted({}).get(); }

// The public functions, through the module: an error saying why when it cannot be loaded.
namespace {
template <class R, class... Parameters, class... Arguments>
R throughCodecs(R (*const ImageCodecs::*function)(Parameters...), Arguments&&... arguments) {
    const auto& codecs = imageCodecs();
    if (!codecs) return Error{codecs.error()};
    return ((*codecs)->*function)(std::forward<Arguments>(arguments)...);
}
}  // namespace

Result<Image> readImage(const fs::path& file) { return throughCodecs(&ImageCodecs::readImage, file); }

Result<Image> readVolumeImage(const fs::path& file) { return throughCodecs(&ImageCodecs::readVolumeImage, file); }

Result<void> writeImage(const fs::path& file, const Image& image, const WriteOptions& options) {
    return throughCodecs(&ImageCodecs::writeImage, file, image, options);
}

Result<void> writeImage(const fs::path& file, const Image& image, DisplayTransform transform) {
    WriteOptions options;
    options.transform = transform;
    return writeImage(file, image, options);
}

Result<InputImage> readInputImage(const fs::path& file, const std::string& layer, int maxSide) {
    return throughCodecs(&ImageCodecs::readInputImage, file, layer, maxSide);
}

Result<Image> resampleImage(const Image& image, int width, int height) {
    return throughCodecs(&ImageCodecs::resampleImage, image, width, height);
}

ImageComparison compareImages(const Image& actual, const Image& reference, const CompareLimits& limits) {
    const auto& codecs = imageCodecs();
    if (!codecs) {
        ImageComparison failed;
        failed.problem = codecs.error();
        return failed;
    }
    return (*codecs)->compareImages(actual, reference, limits);
}

Result<void> checkImageFileMemory(const fs::path& file) { return throughCodecs(&ImageCodecs::checkImageFileMemory, file); }

Result<CubeFaces> readDdsCubeMap(const fs::path& file) { return throughCodecs(&ImageCodecs::readDdsCubeMap, file); }

}  // namespace rmfx

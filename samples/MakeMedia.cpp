// rmfx_make_media [DIR]: writes the computed media of the sample workspaces (default: samples/):
// DIR/tour/ for samples/tour/tour.xml and DIR/media/ for the chapter-8 workspaces in effects/.
// The build runs it, so the workspaces render straight after `cmake --build`.

#include <iostream>

#include "samples/SampleMedia.h"

int main(int argc, char** argv) {
    std::filesystem::path root = argc > 1 ? argv[1] : RMFX_SAMPLES_DIR;
    if (auto r = rmfx::samples::writeTourMedia(root / "tour"); !r) {
        std::cerr << "rmfx_make_media: " << r.error() << "\n";
        return 1;
    }
    if (auto r = rmfx::samples::writeChapterMedia(root / "media"); !r) {
        std::cerr << "rmfx_make_media: " << r.error() << "\n";
        return 1;
    }
    std::cout << "wrote " << (root / "tour").string() << "/{mask.png, sky_cross.exr} and " << (root / "media").string()
              << "/{sky_cross.exr, sky_cross_alpha64.png, ghost_mask.png, hdr_scene.exr}\n";
    return 0;
}

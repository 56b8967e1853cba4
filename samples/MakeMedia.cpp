// rmfx_make_media [DIR]: writes the computed media of the sample workspaces (default: samples/).

#include <iostream>

#include "samples/SampleMedia.h"

int main(int argc, char** argv) {
    std::filesystem::path root = argc > 1 ? argv[1] : RMFX_SAMPLES_DIR;
    if (auto r = rmfx::samples::writeTourMedia(root / "tour"); !r) {
        std::cerr << "rmfx_make_media: " << r.error() << "\n";
        return 1;
    }
    std::cout << "wrote " << (root / "tour").string() << "/mask.png, sky_cross.exr\n";
    return 0;
}

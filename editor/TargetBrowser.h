#pragma once
// The Render targets section: a thumbnail of every target of the current frame (the target's
// texture drawn down into a small texture, sRGB), and a large viewer window for each one clicked;
// then the workspace's volume textures, a slice each.

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "editor/DisplayTexture.h"
#include "editor/TargetHealthBadge.h"
#include "editor/TargetViewer.h"
#include "editor/TextureBlit.h"
#include "gl/GlExecutor.h"

namespace rmfx::editor {

inline constexpr int thumbnailSize = 84;  // the longer side, pixels

class TargetBrowser {
public:
    // The output target is shown with the workspace's output transform, the others with sRGB.
    void setOutput(const std::string& target, DisplayTransform transform);
    // After a frame: draws every target's thumbnail (GL; leaves framebuffer 0 bound), notes the
    // targets no pass of that frame wrote (their effect switched off, say) and, with the health
    // check on, what each target holds (a badge under its thumbnail).
    void updateThumbnails(GlExecutor& executor, const Workspace& ws, TextureBlit& blit);
    // The section's contents: the thumbnails; a click opens (or focuses) the target's viewer.
    void draw(const GlExecutor& executor);
    // The open viewers' windows; new ones appear near `firstPosition`, `firstSize` large.
    void drawViewers(const GlExecutor& executor, glm::vec2 firstPosition, glm::vec2 firstSize);
    // Opens a viewer (as a click on its thumbnail does).
    void open(const std::string& target);

private:
    struct Thumbnail {
        std::string target;
        std::unique_ptr<DisplayTexture> texture;
    };
    // A volume (3D) texture of the workspace, shown one slice at a time (a slider picks it).
    struct VolumeThumbnail {
        std::string texture;
        std::unique_ptr<DisplayTexture> image;
        glm::ivec3 size{0};
        float slice = 0.5f;  // r in [0, 1]
    };
    void updateVolumes(const GlExecutor& executor, const Workspace& ws, TextureBlit& blit);
    void drawVolumes();
    std::vector<Thumbnail> thumbnails_;
    std::vector<VolumeThumbnail> volumes_;
    std::vector<std::unique_ptr<TargetViewer>> viewers_;
    std::string focus_;
    std::set<std::string> written_;  // by the last frame
    std::map<std::string, TargetHealthBadge> health_;  // of the last frame; empty with the check off
    std::string output_;
    DisplayTransform outputTransform_ = DisplayTransform::Srgb;
    DisplayTransform transformOf(const std::string& target) const;
};

}  // namespace rmfx::editor

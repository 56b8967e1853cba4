#pragma once
// Headless contexts for a run that renders several workspaces (rmfx replay): one per profile,
// created when a workspace first asks for it and kept, so that each workspace runs in the
// context its profile needs.

#include <map>
#include <memory>

#include "gl/GlContext.h"

namespace rmfx {

class HeadlessContexts {
public:
    // Makes the context of `profile` current, creating it on first use; an error says why it
    // cannot be created (asked again, it is tried again).
    Result<GlContext*> use(GlProfile profile);

private:
    std::map<GlProfile, std::unique_ptr<GlContext>> contexts_;
};

}  // namespace rmfx

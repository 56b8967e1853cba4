#include "gl/HeadlessContexts.h"

namespace rmfx {

Result<GlContext*> HeadlessContexts::use(GlProfile profile) {
    auto& slot = contexts_[profile];
    if (!slot) {
        auto created = GlContext::createHeadless(profile);
        if (!created) return Error{created.error()};
        slot = std::move(*created);
    }
    slot->makeCurrent();
    return slot.get();
}

}  // namespace rmfx

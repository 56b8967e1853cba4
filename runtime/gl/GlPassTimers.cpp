#include "gl/GlPassTimers.h"

#include <epoxy/gl.h>

namespace rmfx {

void GlPassTimers::setEnabled(bool enabled) {
    enabled_ = enabled;
    if (!enabled) {
        for (Frame& f : frames_) f.pending = false;
        timings_.clear();
        frameMilliseconds_ = 0.0;
    }
}

void GlPassTimers::collect(bool waitForNext) {
    for (int k = 0; k < 3; ++k) {
        Frame& f = frames_[(next_ + k) % 3];
        if (!f.pending) continue;
        GLint available = 0;
        glGetQueryObjectiv(f.queries.back().get(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available && !(waitForNext && k == 0)) continue;
        std::vector<GLuint64> stamps(f.queries.size());
        for (size_t i = 0; i < f.queries.size(); ++i) glGetQueryObjectui64v(f.queries[i].get(), GL_QUERY_RESULT, &stamps[i]);
        timings_.clear();
        for (size_t i = 0; i < f.passes.size(); ++i)
            timings_.push_back({f.passes[i], static_cast<double>(stamps[i + 1] - stamps[i]) * 1e-6});
        frameMilliseconds_ = static_cast<double>(stamps.back() - stamps.front()) * 1e-6;
        f.pending = false;
    }
}

void GlPassTimers::beginFrame(size_t passCount) {
    current_ = nullptr;
    if (!enabled_) return;
    collect(true);
    Frame& f = frames_[next_];
    next_ = (next_ + 1) % 3;
    if (f.queries.size() != passCount + 1) {
        f.queries.clear();
        for (size_t i = 0; i < passCount + 1; ++i) f.queries.push_back(createQuery(GL_TIMESTAMP));
    }
    f.passes.clear();
    f.pending = true;
    glQueryCounter(f.queries[0].get(), GL_TIMESTAMP);
    current_ = &f;
}

void GlPassTimers::passDone(const std::string& pass) {
    if (!current_) return;
    current_->passes.push_back(pass);
    glQueryCounter(current_->queries[current_->passes.size()].get(), GL_TIMESTAMP);
}

const std::vector<PassTiming>& GlPassTimers::timings() {
    collect(false);
    return timings_;
}

}  // namespace rmfx

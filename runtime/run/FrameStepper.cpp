#include "run/FrameStepper.h"

#include <utility>

#include <epoxy/gl.h>

namespace rmfx {

FrameStepper::FrameStepper(float dt, double budgetSeconds, std::function<void(const std::string&)> onBudget, float origin)
    : dt_(dt), origin_(origin) {
    if (budgetSeconds > 0) watchdog_.emplace(budgetSeconds, std::move(onBudget));
}

Result<void> FrameStepper::step(GlExecutor& executor, long index, const std::string& label) {
    if (watchdog_) watchdog_->arm(label);
    Diagnostics frame = executor.renderFrame({time(index), dt_}).takeDiagnostics();
    if (watchdog_) {
        glFinish();
        watchdog_->disarm();
    }
    return Result<void>(std::move(frame));
}

Result<Image> FrameStepper::stepAndRead(GlExecutor& executor, long index, const std::string& label, const std::string& target) {
    if (watchdog_) watchdog_->arm(label);
    Result<void> rendered = executor.renderFrame({time(index), dt_});
    if (!rendered) {
        if (watchdog_) watchdog_->disarm();
        return Result<Image>::failure(rendered.takeDiagnostics());
    }
    Diagnostics warnings = rendered.takeDiagnostics();
    Result<Image> image = executor.readTarget(target);
    if (watchdog_) watchdog_->disarm();
    if (!image) return image;
    return Result<Image>(std::move(*image), std::move(warnings));
}

}  // namespace rmfx

#include "editor/TimingHistory.h"

namespace rmfx::editor {

void TimingHistory::add(const std::vector<PassTiming>& passes, double frameMilliseconds) {
    if (passes.empty() || capacity_ == 0) return;
    std::vector<std::string> names;
    Frame frame;
    for (const PassTiming& p : passes) {
        names.push_back(p.pass);
        frame.passes.push_back(p.milliseconds);
    }
    frame.total = frameMilliseconds;
    if (names != names_) {
        frames_.clear();
        names_ = std::move(names);
    }
    frames_.push_back(std::move(frame));
    while (frames_.size() > capacity_) frames_.pop_front();
}

void TimingHistory::clear() {
    frames_.clear();
    names_.clear();
}

std::vector<TimingHistory::Row> TimingHistory::rows() const {
    std::vector<Row> rows;
    if (frames_.empty()) return rows;
    for (std::size_t i = 0; i < names_.size(); ++i) {
        Row r;
        r.pass = names_[i];
        r.lastMilliseconds = frames_.back().passes[i];
        double sum = 0.0;
        for (const Frame& f : frames_) sum += f.passes[i];
        r.averageMilliseconds = sum / static_cast<double>(frames_.size());
        rows.push_back(std::move(r));
    }
    return rows;
}

double TimingHistory::lastFrameMilliseconds() const { return frames_.empty() ? 0.0 : frames_.back().total; }

double TimingHistory::averageFrameMilliseconds() const {
    if (frames_.empty()) return 0.0;
    double sum = 0.0;
    for (const Frame& f : frames_) sum += f.total;
    return sum / static_cast<double>(frames_.size());
}

std::vector<float> TimingHistory::frameTotals() const {
    std::vector<float> totals;
    for (const Frame& f : frames_) totals.push_back(static_cast<float>(f.total));
    return totals;
}

}  // namespace rmfx::editor

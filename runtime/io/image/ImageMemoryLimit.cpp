#include "io/image/ImageMemoryLimit.h"

#include <atomic>

namespace rmfx {
namespace {

// Read by the sequence's reading thread while the main one renders.
std::atomic<std::uint64_t> limit{kDefaultImageMemoryLimit};

}  // namespace

std::uint64_t imageMemoryLimit() { return limit.load(); }

void setImageMemoryLimit(std::uint64_t bytes) { limit.store(bytes); }

}  // namespace rmfx

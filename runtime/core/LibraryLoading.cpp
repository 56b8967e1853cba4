#include "core/LibraryLoading.h"

#include <atomic>

namespace rmfx {
namespace {
std::atomic<int> loads{0};
}  // namespace

LibraryLoadingScope::LibraryLoadingScope() { loads.fetch_add(1); }
LibraryLoadingScope::~LibraryLoadingScope() { loads.fetch_sub(1); }

bool libraryLoadingElsewhere() { return loads.load() > 0; }

}  // namespace rmfx

#pragma once
// Whether a shared library is being loaded (dlopen) on another thread of this process. While one
// is, creating a thread waits for the load to finish (glibc holds its TLS lock, which
// pthread_create needs, through the load), so work that would fan out to new threads runs on the
// calling thread instead: rmfx render loads OpenImageIO on a thread of its own while validation
// compiles on the main one (io/image/ImageCodecs.h).

namespace rmfx {

// Marks a load under way for its lifetime.
class LibraryLoadingScope {
public:
    LibraryLoadingScope();
    ~LibraryLoadingScope();
    LibraryLoadingScope(const LibraryLoadingScope&) = delete;
    LibraryLoadingScope& operator=(const LibraryLoadingScope&) = delete;
};

bool libraryLoadingElsewhere();

}  // namespace rmfx

#include "io/media/SequenceChunk.h"

#include <algorithm>

namespace rmfx {

SequenceChunk planSequenceChunk(int first, int preroll) {
    SequenceChunk chunk;
    chunk.start = std::max(0, first - preroll);
    chunk.skip = first - chunk.start;
    chunk.preroll = std::max(0, preroll - first);
    return chunk;
}

}  // namespace rmfx

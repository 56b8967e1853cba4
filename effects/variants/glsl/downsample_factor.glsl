#pragma once
// The Downsample factor (2, 4 or 8) of a reduced target, from its size and the full size: the
// smallest factor n with ceil(full / n) == reduced on both axes (the runtime's rounding of
// scale="1/n"). Read from sizes, never from the variable, so the shader keeps working whichever
// way the target's scale is chosen. Where two factors give the same size (an axis of 1 or 2
// pixels) both cover the whole axis with one block, so the choice changes nothing. Sizes that no
// factor gives (a viewport that is not the input's size) get the smallest block covering the image.
int downsampleFactor(ivec2 fullSize, ivec2 reducedSize) {
    for (int n = 2; n <= 8; n *= 2)
        if (all(equal((fullSize + n - 1) / n, reducedSize))) return n;
    ivec2 cover = (fullSize + reducedSize - 1) / reducedSize;
    return max(cover.x, cover.y);
}

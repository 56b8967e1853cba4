#pragma once
// Shared by the two adaptations (hdr_adapt.frag, exposure_adapt.frag).
// One step of an exponential approach from `from` to `to` that took `next` (rate > 0): in float32
// the step rounds away once the distance is under about 0.5 / rate ulps, and the value would
// stall (or wobble by an ulp) short of the target forever. A step that did not get closer, within
// 1e-4 relative of the target, lands on the target instead (the exact fixed point). Farther away
// (a rate too small for float32 to move at all) it stays where it is rather than jump.
float settleOnTarget(float from, float to, float next) {
    bool closer = abs(next - to) < abs(from - to);
    bool near = abs(from - to) <= 1e-4 * max(abs(from), abs(to));
    return !closer && near ? to : next;
}

#pragma once
// The HDRLighting sample's bright-pass filter, and the bound that the glare's gate tests
// (hdr_glare_gate.frag): what stays bright after exposure to the key, minus a threshold, mapped
// into 0..1 with a large offset so that lights stand out from lit surfaces.
#include "finite.glsl"
#include "tonemap.glsl"

const float BRIGHT_PASS_THRESHOLD = 5.0;
const float BRIGHT_PASS_OFFSET = 10.0;

vec3 brightPass(vec3 c, float key, float adaptedLuminance) {
    vec3 bright = max(exposeToKey(c, key, adaptedLuminance) - BRIGHT_PASS_THRESHOLD, 0.0);
    return bright / (BRIGHT_PASS_OFFSET + bright);
}

// What brightestChannel gives a colour with a NaN or infinite channel (max() need not keep a NaN,
// and brightPass of one need not be zero): finite, so that the statistics that carry it hold
// nothing the health check would report. (A maximum of them starts from 0, not from -Inf: the
// threshold is positive, so a bound raised to 0 still bounds.)
const float BRIGHTEST_NOT_FINITE = 3.0e38;

// The largest channel of a colour as brightPass sees it.
float brightestChannel(vec3 c) { return all(isFiniteVec3(c)) ? max(c.r, max(c.g, c.b)) : BRIGHTEST_NOT_FINITE; }

// False only where brightPass gives zero in every channel of every colour whose channels are all
// at most `brightest`: c * scale <= brightest * scale for a scale >= 0, and each is at most the
// threshold. The factor 1.001 covers the bright pass's own rounding (another shader, which may
// divide or fuse differently: a few ulps); a negative or non-finite scale, or a NaN or infinite
// channel (or one as large as BRIGHTEST_NOT_FINITE), answers true.
bool brightPassMayPass(float brightest, float key, float adaptedLuminance) {
    float scale = exposureScale(key, adaptedLuminance);
    if (!(brightest < BRIGHTEST_NOT_FINITE) || !isFiniteFloat(scale) || scale < 0.0) return true;
    return brightest * scale * 1.001 > BRIGHT_PASS_THRESHOLD;
}

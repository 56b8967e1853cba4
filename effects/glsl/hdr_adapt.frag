// Light adaptation: the adapted luminance follows the measured one, 2% of the way per 1/30 s,
// whatever the frame rate: adapted += (current - adapted) (1 - 0.98^(30 dt)). Kept in r32f: in
// r16f the step falls below half-float resolution and the adaptation stalls short of its target.
#include "adaptation.glsl"
#include "finite.glsl"
#include "luminance.glsl"
uniform sampler2D Adapted_Previous;
uniform sampler2D Measured;
uniform float rm_DeltaTime;
uniform bool Light_Adaptation;
out vec4 fragColor;

// The smallest log-average the chain can measure (exp(mean(log(delta + Y))) >= delta): a measured
// 0 or 1e-10 (written by hand, or a broken chain) adapts to this, so 1 / adapted stays finite.
const float MIN_ADAPTED_LUMINANCE = LOG_DELTA;

void main() {
    float current = texelFetch(Measured, ivec2(0), 0).r;
    float adapted = texelFetch(Adapted_Previous, ivec2(0), 0).r;
    // A NaN or infinite measurement is dropped (the adapted value stays); a NaN or infinite
    // adapted value (a bad initial value) restarts from the measurement. Neither is ever stored.
    if (!isFiniteFloat(adapted)) adapted = isFiniteFloat(current) ? current : 1.0;
    if (!isFiniteFloat(current)) current = adapted;
    current = max(current, MIN_ADAPTED_LUMINANCE);
    adapted = max(adapted, MIN_ADAPTED_LUMINANCE);
    float rate = Light_Adaptation ? 1.0 - pow(0.98, 30.0 * max(rm_DeltaTime, 0.0)) : 1.0;
    // Written so that rate 0 (dt = 0) keeps the adapted value and rate 1 (a long dt, or no
    // adaptation) gives the measured one, both exactly.
    float next = adapted * (1.0 - rate) + current * rate;
    // Without this, float32 stalls 0.5 / rate ulps short (6e-6 relative at 60 Hz).
    if (rate > 0.0) next = settleOnTarget(adapted, current, next);
    fragColor = vec4(next, 0.0, 0.0, 1.0);
}

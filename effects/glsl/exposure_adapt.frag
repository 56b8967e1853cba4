// The chapter's automatic exposure, once per frame (whatever the frame's dt, as in the chapter):
//   Exposure = lerp(Exposure, 0.5 / Average_Brightness, Exposure_Adjust_Speed)
// starting from Initial_Exposure on the first frame. The average is floored at
// Minimum_Average_Brightness so that a black scene gives a large but finite exposure.
#include "adaptation.glsl"
#include "finite.glsl"
uniform sampler2D Previous_Exposure;
uniform sampler2D Average_Brightness;
uniform float Exposure_Adjust_Speed;
uniform float Initial_Exposure;
uniform float Minimum_Average_Brightness;
uniform int rm_Frame;
out vec4 fragColor;

void main() {
    float exposure = rm_Frame == 0 ? Initial_Exposure : texelFetch(Previous_Exposure, ivec2(0), 0).r;
    float average = texelFetch(Average_Brightness, ivec2(0), 0).r;
    float floorAverage = max(Minimum_Average_Brightness, 1e-30);
    // A NaN or infinite average (a NaN texel reached the chain) is dropped: the exposure stays. A
    // NaN or infinite exposure (a bad Initial_Exposure) restarts at the target. Neither is stored.
    float target = isFiniteFloat(average) ? 0.5 / max(average, floorAverage) : -1.0;
    if (!isFiniteFloat(exposure)) exposure = target >= 0.0 ? target : 1.0;
    if (target < 0.0) target = exposure;
    float speed = clamp(Exposure_Adjust_Speed, 0.0, 1.0);
    float next = mix(exposure, target, speed);
    if (speed > 0.0) next = settleOnTarget(exposure, target, next);
    fragColor = vec4(next, 0.0, 0.0, 1.0);
}

// Light adaptation: the adapted luminance follows the measured one, 2% of the way per 1/30 s,
// whatever the frame rate: adapted += (current - adapted) (1 - 0.98^(30 dt)). Kept in r32f: in
// r16f the step falls below half-float resolution and the adaptation stalls short of its target.
uniform sampler2D Adapted_Previous;
uniform sampler2D Measured;
uniform float rm_DeltaTime;
uniform bool Light_Adaptation;
out vec4 fragColor;

void main() {
    float current = texelFetch(Measured, ivec2(0), 0).r;
    float adapted = texelFetch(Adapted_Previous, ivec2(0), 0).r;
    float rate = Light_Adaptation ? 1.0 - pow(0.98, 30.0 * rm_DeltaTime) : 1.0;
    fragColor = vec4(adapted + (current - adapted) * rate, 0.0, 0.0, 1.0);
}

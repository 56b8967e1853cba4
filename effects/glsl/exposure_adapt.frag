// The chapter's automatic exposure, once per frame:
//   Exposure = lerp(Exposure, 0.5 / Average_Brightness, Exposure_Adjust_Speed)
// starting from Initial_Exposure on the first frame. The average is floored at
// Minimum_Average_Brightness so that a black scene gives a large but finite exposure.
uniform sampler2D Previous_Exposure;
uniform sampler2D Average_Brightness;
uniform float Exposure_Adjust_Speed;
uniform float Initial_Exposure;
uniform float Minimum_Average_Brightness;
uniform int rm_Frame;
out vec4 fragColor;

void main() {
    float exposure = rm_Frame == 0 ? Initial_Exposure : texelFetch(Previous_Exposure, ivec2(0), 0).r;
    float average = max(texelFetch(Average_Brightness, ivec2(0), 0).r, Minimum_Average_Brightness);
    fragColor = vec4(mix(exposure, 0.5 / average, Exposure_Adjust_Speed), 0.0, 0.0, 1.0);
}

#pragma once
// The star (cross-screen filter) glare of the HDRLighting sample, after Kawase: each line of the
// star is drawn by STAR_PASSES passes of STAR_SAMPLES bilinear taps along the line's direction,
// the step growing 8x per pass (1, 8, 64 texels), so three passes reach 8^3 texels. Star_Type:
// 0 Cross, 1 CrossFilter, 2 SnowCross, 3 Vertical, 4 SunnyCross.

const int STAR_PASSES = 3;
const int STAR_SAMPLES = 8;
const int STAR_MAX_LINES = 8;

int starLineCount(int type) {
    const int lines[5] = int[5](4, 4, 6, 2, 8);
    return lines[clamp(type, 0, 4)];
}

float starAttenuation(int type, int line) {
    if (type == 4) return line % 2 == 0 ? 0.95 : 0.88;  // SunnyCross: long and short lines alternate
    const float attenuation[4] = float[4](0.85, 0.95, 0.96, 0.96);
    return attenuation[clamp(type, 0, 3)];
}

// Lines are evenly spread from the type's inclination (SnowCross: 20 degrees), clockwise from up.
float starLineAngle(int type, int line) {
    float inclination = type == 2 ? radians(20.0) : 0.0;
    return inclination + radians(360.0) / float(starLineCount(type)) * float(line);
}

// Colour of sample s in pass p: the chromatic table blended towards white (0.63) as the pass's
// reach grows, then towards white again by 1 - chromaticAberration.
vec3 starColor(int pass, int s, float chromaticAberration) {
    const vec3 white = vec3(0.63);
    const vec3 chromatic[8] = vec3[8](vec3(0.5, 0.5, 0.5), vec3(0.8, 0.3, 0.3), vec3(1.0, 0.2, 0.2),
                                      vec3(0.5, 0.2, 0.6), vec3(0.2, 0.2, 1.0), vec3(0.2, 0.3, 0.7),
                                      vec3(0.2, 0.6, 0.2), vec3(0.3, 0.5, 0.3));
    float ratio = float(pass + 1) / float(STAR_PASSES);
    return mix(white, mix(chromatic[s], white, ratio), chromaticAberration);
}

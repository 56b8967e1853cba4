#pragma once
// The HDRLighting scene: a dim room lit by two small emissive spheres of high radiance (and an
// emissive panel that only glows). Light i is a sphere of radius r and radiance L; seen from a
// distance d it acts as a point light of intensity pi L r², so a surface of albedo a reflects
// a L r² cos(theta) / d² (Lambert) plus a glossy highlight.
uniform float Light0_Radiance;
uniform float Light1_Radiance;
uniform float Panel_Radiance;
uniform float Ambient_Radiance;

const vec3 LIGHT_POSITION[2] = vec3[2](vec3(-1.3, 0.95, 0.7), vec3(1.35, 0.2, 1.1));
const float LIGHT_RADIUS[2] = float[2](0.18, 0.12);
const vec3 LIGHT_COLOR[2] = vec3[2](vec3(1.0, 0.8, 0.55), vec3(0.55, 0.75, 1.0));
const vec3 PANEL_COLOR = vec3(1.0, 0.95, 0.9);

// Emitted radiance of light 0 or 1, or of the panel (2).
vec3 emission(int light) {
    if (light == 0) return LIGHT_COLOR[0] * Light0_Radiance;
    if (light == 1) return LIGHT_COLOR[1] * Light1_Radiance;
    return PANEL_COLOR * Panel_Radiance;
}

vec3 shadeSurface(vec3 albedo, float glossiness, vec3 position, vec3 normal, vec3 eye) {
    vec3 n = normalize(normal);
    vec3 v = normalize(eye - position);
    if (dot(n, v) < 0.0) n = -n;  // planes are seen from both sides
    vec3 color = Ambient_Radiance * albedo;
    for (int i = 0; i < 2; ++i) {
        vec3 toLight = LIGHT_POSITION[i] - position;
        float d2 = dot(toLight, toLight);
        vec3 l = toLight * inversesqrt(d2);
        float cosTheta = max(dot(n, l), 0.0);
        float highlight = glossiness * (64.0 + 8.0) / 8.0 * pow(max(dot(n, normalize(l + v)), 0.0), 64.0);
        color += (albedo + highlight) * emission(i) * (LIGHT_RADIUS[i] * LIGHT_RADIUS[i] * cosTheta / d2);
    }
    return color;
}

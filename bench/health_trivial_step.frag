#version 450 core
// One step of bench/health_trivial_passes.xml: next to nothing per fragment.
uniform sampler2D S;
out vec4 c;
void main() { c = texelFetch(S, ivec2(gl_FragCoord.xy), 0) * 0.99 + 0.01; }

// One level of the average-brightness chain: each pixel is the weighted mean of the up to 2x2
// source texels it covers (pixel x covers source columns 2x and 2x+1, the latter only when it
// exists, so odd sizes lose no edge). Output: r = mean brightness of the scene pixels under this
// pixel, g = how many scene pixels that is. Source_Is_Scene: the source is the HDR scene (each
// texel is one scene pixel of brightness(rgb)); otherwise a previous level (r mean, g count).
#include "brightness.glsl"
uniform sampler2D Source;
uniform bool Source_Is_Scene;
out vec4 fragColor;

void main() {
    ivec2 sourceSize = textureSize(Source, 0);
    ivec2 first = 2 * ivec2(gl_FragCoord.xy);
    ivec2 last = min(first + 1, sourceSize - 1);
    float means[4];
    float counts[4];
    float total = 0.0;
    int n = 0;
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) {
            vec4 texel = texelFetch(Source, ivec2(x, y), 0);
            means[n] = Source_Is_Scene ? brightness(texel.rgb) : texel.r;
            counts[n] = Source_Is_Scene ? 1.0 : texel.g;
            total += counts[n];
            ++n;
        }
    // Weights count/total: a single texel (a 1x1 level copied to the next) gets weight exactly 1,
    // so the extra levels declared for large viewports leave the value unchanged.
    float mean = 0.0;
    for (int i = 0; i < n; ++i) mean += means[i] * (counts[i] / total);
    fragColor = vec4(mean, total, 0.0, 1.0);
}

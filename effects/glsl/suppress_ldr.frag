// The article's downsample: one bilinear fetch of the full-size scene per pixel of the 1/4 target,
// times the material colour Kd, kept only where a channel exceeds 1 (SuppressLDR) so that only
// HDR highlights bloom.
uniform sampler2D DownSampler;
uniform vec3 Kd;
in vec2 vTexCoord;
out vec4 fragColor;

void main() {
    vec4 color = texture(DownSampler, vTexCoord) * vec4(Kd, 1.0);
    fragColor = any(greaterThan(color.rgb, vec3(1.0))) ? color : vec4(0.0);
}

// One glare blur pass with the 49-sample Gauss filter (exercise 1): the 7x7 binomial, the outer
// product of (1 6 15 20 15 6 1) / 64 with itself, sampling Texture0 whole texels of the target
// being rendered apart. It equals three passes of gauss9.frag (binomial of order 6 = three of
// order 2), so its variance is 1.5 texel² per axis against 0.5 for the 9-sample filter.
uniform sampler2D Texture0;
uniform vec2 rm_InvTargetSize;
in vec2 vTexCoord;
out vec4 fragColor;

const float binomial[7] = float[7](1.0, 6.0, 15.0, 20.0, 15.0, 6.0, 1.0);

void main() {
    vec4 color = vec4(0.0);
    for (int y = -3; y <= 3; y++)
        for (int x = -3; x <= 3; x++)
            color += (binomial[x + 3] * binomial[y + 3] / 4096.0) *
                     texture(Texture0, vTexCoord + vec2(x, y) * rm_InvTargetSize);
    fragColor = color;
}

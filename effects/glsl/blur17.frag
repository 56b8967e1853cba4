// One axis of the article's separable blur: the centre and 8 taps on either side, one texel
// apart along BlurDirection (1 0 for X, 0 1 for Y), weighted by the binomial coefficients
// C(16, 8 ± i) / 2^16 — a Gaussian of sigma 2 texels whose weights sum to exactly 1.
uniform sampler2D BlurSampler;
uniform vec2 BlurDirection;
uniform vec2 rm_InvTargetSize;
in vec2 vTexCoord;
out vec4 fragColor;

const float PixelWeight[9] = float[9](12870.0, 11440.0, 8008.0, 4368.0, 1820.0, 560.0, 120.0, 16.0, 1.0);

void main() {
    vec2 BlurOffset = BlurDirection * rm_InvTargetSize;
    vec4 color = texture(BlurSampler, vTexCoord) * PixelWeight[0];
    for (int i = 1; i <= 8; ++i) {
        color += texture(BlurSampler, vTexCoord + BlurOffset * float(i)) * PixelWeight[i];
        color += texture(BlurSampler, vTexCoord - BlurOffset * float(i)) * PixelWeight[i];
    }
    fragColor = color / 65536.0;
}

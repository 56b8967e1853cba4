// An effect as ReShade's community writes them, for rmfx's tests.
#include "FixtureCommon.fxh"
#include "FixtureCommon.fxh" // #pragma once: nothing the second time

#ifndef FIXTURE_BLUR_RADIUS
	#define FIXTURE_BLUR_RADIUS 4 // taps on each side
#endif

#if __RESHADE__ < 30101
	#define FIXTURE_UI_TYPE "drag"
#else
	#define FIXTURE_UI_TYPE "slider"
#endif

#define STRINGIFY(x) #x
#define TO_STRING(x) STRINGIFY(x)

uniform float Strength < ui_type = FIXTURE_UI_TYPE; ui_label = "Strength (radius " TO_STRING(FIXTURE_BLUR_RADIUS) ")"; > = 1.0;

FIXTURE_TARGET(Blur, RGBA16F);

float4 PS_Blur(float4 pos : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	float4 sum = 0;
	[unroll] for (int i = -FIXTURE_BLUR_RADIUS; i <= FIXTURE_BLUR_RADIUS; ++i)
		sum += tex2D(BlurSampler, uv + float2(i, 0) * BUFFER_PIXEL_SIZE);
	return sum / (2 * FIXTURE_BLUR_RADIUS + 1) * Strength * Fixture::GetDepth(uv);
}

technique FixtureBlur < ui_tooltip = "Made for " __FILE_STEM__ " on line " TO_STRING(__LINE__); >
{
	pass
	{
#if FIXTURE_SUPPORTED(4, 0, 0) && BUFFER_WIDTH > BUFFER_HEIGHT
		VertexShader = PostProcessVS;
#endif
		PixelShader = PS_Blur;
		RenderTarget = BlurTex;
	}
}

// A small stand-in for ReShade.fxh, written for rmfx's parser tests: the declarations real effects
// rely on (not a copy of ReShade's file).
#pragma once

#define BUFFER_PIXEL_SIZE float2(BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT)
#define BUFFER_SCREEN_SIZE float2(BUFFER_WIDTH, BUFFER_HEIGHT)

namespace ReShade
{
	static const float2 PixelSize = BUFFER_PIXEL_SIZE;
	static const float2 ScreenSize = BUFFER_SCREEN_SIZE;

	texture BackBufferTex : COLOR;
	texture DepthBufferTex : DEPTH;
	sampler BackBuffer { Texture = BackBufferTex; };
	sampler DepthBuffer { Texture = DepthBufferTex; };

	float GetLinearizedDepth(float2 texcoord)
	{
		float depth = tex2Dlod(DepthBuffer, float4(texcoord, 0, 0)).x;
		const float N = 1.0;
		depth /= 1000.0 - depth * (1000.0 - N);
		return depth;
	}
}

// A triangle that covers the screen
void PostProcessVS(in uint id : SV_VertexID, out float4 position : SV_Position, out float2 texcoord : TEXCOORD)
{
	texcoord.x = (id == 2) ? 2.0 : 0.0;
	texcoord.y = (id == 1) ? 2.0 : 0.0;
	position = float4(texcoord * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
}

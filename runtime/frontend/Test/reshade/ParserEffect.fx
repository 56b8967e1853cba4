// A two-technique effect as ReShade's community writes them, for rmfx's parser tests.
#include "ParserCommon.fxh"

uniform int BlurMode <
	ui_type = "combo";
	ui_items = "Box\0Gaussian\0";
	ui_label = "Blur mode";
> = 1;

uniform float Intensity < ui_type = "slider"; ui_min = 0.0; ui_max = 2.0; ui_category = "Bloom"; > = 0.8;
uniform float Timer < source = "timer"; >;

texture HalfTex { Width = BUFFER_WIDTH / 2; Height = BUFFER_HEIGHT / 2; Format = RGBA16F; };
sampler HalfSampler { Texture = HalfTex; AddressU = MIRROR; AddressV = MIRROR; MagFilter = LINEAR; MinFilter = POINT; };
texture HistTex { Width = 256; Height = 1; Format = R32F; };
storage HistStorage { Texture = HistTex; };

float4 BlurPS(float4 pos : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	float4 sum = 0;
	[unroll] for (int i = -2; i <= 2; ++i)
	{
		float2 offset = float2(i, 0) * ReShade::PixelSize * (BlurMode == 1 ? 1.5 : 1.0);
		sum += tex2D(ReShade::BackBuffer, uv + offset);
	}
	return sum / 5;
}

float4 CombinePS(float4 pos : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	return tex2D(ReShade::BackBuffer, uv) + tex2D(HalfSampler, uv) * Intensity;
}

groupshared uint Bins[64];
void HistogramCS(uint3 id : SV_DispatchThreadID, uint3 tid : SV_GroupThreadID)
{
	if (tid.x == 0) { Bins[tid.y] = 0; }
	barrier();
	tex2Dstore(HistStorage, id.xy, float4(Bins[tid.y], 0, 0, 0));
}

technique FixtureBloom < ui_label = "Fixture Bloom"; ui_tooltip = "Blurs at half size, then adds it back"; >
{
	pass Blur
	{
		VertexShader = PostProcessVS;
		PixelShader = BlurPS;
		RenderTarget = HalfTex;
	}
	pass Combine
	{
		VertexShader = PostProcessVS;
		PixelShader = CombinePS;
		BlendEnable = true;
		SrcBlend = ONE;
		DestBlend = INVSRCALPHA;
	}
}

technique FixtureHistogram < enabled = false; hidden = true; >
{
	pass
	{
		ComputeShader = HistogramCS<8, 8>;
		DispatchSizeX = 256 / 8;
		DispatchSizeY = 1;
	}
}

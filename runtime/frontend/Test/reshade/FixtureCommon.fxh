// A small stand-in for ReShade.fxh, written for rmfx's tests: the macros and patterns real
// effects rely on (not a copy of ReShade's file).
#pragma once

#if !defined(__RESHADE__) || __RESHADE__ < 30000
	#error "ReShade 3.0+ is required to use this header file"
#endif

#ifndef RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN
	#define RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN 0
#endif
#ifndef RESHADE_DEPTH_INPUT_IS_REVERSED
	#define RESHADE_DEPTH_INPUT_IS_REVERSED 1
#endif

#define BUFFER_PIXEL_SIZE float2(BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT)
#define BUFFER_SCREEN_SIZE float2(BUFFER_WIDTH, BUFFER_HEIGHT)
#define BUFFER_ASPECT_RATIO (BUFFER_WIDTH * BUFFER_RCP_HEIGHT)

#define FIXTURE_VERSION(major, minor, build) (10000 * (major) + 100 * (minor) + (build))
#define FIXTURE_SUPPORTED(major, minor, build) (__RESHADE__ >= FIXTURE_VERSION(major, minor, build))

// Declares a texture and its sampler in one go: NAME##Tex and NAME##Sampler.
#define FIXTURE_TARGET(NAME, FORMAT) \
	texture NAME##Tex { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; Format = FORMAT; }; \
	sampler NAME##Sampler { Texture = NAME##Tex; }

namespace Fixture
{
	float GetDepth(float2 texcoord)
	{
#if RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN
		texcoord.y = 1.0 - texcoord.y;
#endif
		float depth = tex2Dlod(DepthBuffer, float4(texcoord, 0, 0)).x;
#if RESHADE_DEPTH_INPUT_IS_REVERSED
		depth = 1 - depth;
#endif
		return depth;
	}
}

#pragma once
// The values RenderMonkey fills for variables marked with a VARIABLE_SEMANTIC (Variable::semantic):
// the World/View/Projection matrices and their products, inverses and transposes, the camera,
// cycling time, the viewport, the pass index, per-pass random numbers and the mouse. Computed in
// double and handed over as a Value of the semantic's type.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "core/Value.h"
#include "model/UniformType.h"

namespace rmfx {

struct SemanticInfo {
    int id;             // index in semanticVariables()
    const char* name;   // as RenderMonkey spells it: "WorldViewProjectionInverseTranspose"
    UniformType type;   // Float, Vec2, Vec4 or Mat4
    const char* meaning;
};

// Every semantic rmfx fills, in a stable order (docs/rendermonkey.md lists them).
std::span<const SemanticInfo> semanticVariables();
// By name, ignoring case (RenderMonkey files are not consistent); nullopt for an unknown semantic.
std::optional<SemanticInfo> findSemantic(std::string_view name);

// Whether a uniform of `uniform` type can take the semantic's value: the same type, a scalar into
// an int or bool, or a shorter vector (vec3 takes ViewPosition's xyz). Matrices only into mat4.
bool semanticFeeds(const SemanticInfo& semantic, UniformType uniform);

inline constexpr double kDefaultTimeCyclePeriod = 120.0;  // seconds: Time0_X wraps to 0 after it

// What a draw sees: the matrices in OpenGL's column-vector convention (clip = P·V·W·x).
struct SemanticInputs {
    glm::dmat4 world{1.0}, view{1.0}, projection{1.0};
    double fovYRadians = 0.0, nearPlane = 0.0, farPlane = 0.0;
    glm::ivec2 viewport{1};
    double time = 0.0;       // seconds since the first frame
    double deltaTime = 0.0;  // seconds since the previous frame
    double cyclePeriod = kDefaultTimeCyclePeriod;
    int frame = 0;
    int passIndex = 0;             // the pass's position in the workspace's pass list, from 0
    glm::dvec2 mouse{0.0};         // pixels from the viewport's top-left corner; 0 headless
    glm::ivec3 mouseButtons{0};    // left, middle, right: 1 while held
};

Value semanticValue(const SemanticInfo& semantic, const SemanticInputs& inputs);

// RandomFraction<k>PerPass / PerEffect: a number in [0, 1) that changes every frame (and every
// pass for PerPass), the same for the same frame and pass so that renders repeat exactly.
double randomFraction(int frame, int pass, int k);

}  // namespace rmfx

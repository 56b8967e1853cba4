#pragma once
// The bench's manifest (bench/variants.xml): the input scenes, and per stage its workspace, its
// ideal, its output target and the axes its variants vary (docs/accuracy-vs-time.md).
//
//   <bench-variants>
//     <scene name="hdr_scene" file="../samples/media/hdr_scene.exr"/>
//     <scene name="shader_5" workspace="../effects/shader_5.xml" target="scene"/>
//     <stage name="bloom" workspace="../effects/variants/bloom.xml" ideal="bloom" output="result">
//       <axis effects="gauss9x1 dual_filter" default="dual_filter" crossed="true"/>
//       <axis variable="Downsample" values="0 1 2" labels="1/2 1/4 1/8" default="1" crossed="true"/>
//       <axis name="percentiles" variables="Histogram_Low Histogram_High" values="0 1, 0.05 0.95"
//             default="0 1" with="histogram"/>
//     </stage>
//   </bench-variants>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"

namespace rmfx::accuracy {

enum class IdealKind { Bloom, Streak, Luminance, ToneMap };
const char* idealKindName(IdealKind kind);

// An input image: an EXR file, or a render target of a workspace rendered at the bench's size.
struct SceneSpec {
    std::string name;
    std::filesystem::path file;       // resolved against the manifest's folder
    std::filesystem::path workspace;  // or this, with `target`
    std::string target;
    SourceLocation where;
};

struct AxisValue {
    std::string label;
    std::vector<std::string> words;  // the effect name, or one value per variable
};

struct VariantAxis {
    std::string name;                    // "effects", the variable, or the name attribute
    bool effects = false;                // values are effect names
    std::vector<std::string> variables;  // else the variables each value sets
    std::vector<AxisValue> values;
    size_t defaultIndex = 0;
    bool crossed = false;                // part of the full cross product
    std::string with;                    // an effect its other values run with (else the default)
    SourceLocation where;
};

struct StageSpec {
    std::string name;
    std::filesystem::path workspace;  // resolved against the manifest's folder
    IdealKind ideal = IdealKind::Bloom;
    std::string output;
    std::vector<VariantAxis> axes;  // exactly one effects axis
    SourceLocation where;

    const VariantAxis& effectsAxis() const;
};

struct VariantManifest {
    std::filesystem::path path;
    std::vector<SceneSpec> scenes;
    std::vector<StageSpec> stages;

    const StageSpec* findStage(const std::string& name) const;
};

// The manifest with its warnings, or the diagnostics with at least one error.
Result<VariantManifest> parseVariantManifestFile(const std::filesystem::path& path);
// `path` names the text in diagnostics; relative paths resolve against its folder.
Result<VariantManifest> parseVariantManifestText(const std::string& text, const std::filesystem::path& path);

// One variant of a stage: the effect it asks for and the variables it sets (every variable axis,
// default or not).
struct Variant {
    std::string name;  // "dual_filter Downsample=1/2 Target_Format=rgba8x64"
    std::string effect;
    std::vector<std::pair<std::string, std::string>> settings;

    std::string settingsText() const;  // "Downsample=0 Target_Format=3"
};

// The full cross product of the crossed axes with the others at their defaults, then each value
// of every other axis with the rest at their defaults (and the effect its `with` names), with no
// duplicates, in that order. Crossed axes always appear in the name; the others when not default.
std::vector<Variant> expandVariants(const StageSpec& stage);

}  // namespace rmfx::accuracy

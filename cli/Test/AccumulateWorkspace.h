#pragma once
// A workspace with state that never fades, for the sequence tests: `sum` adds each frame's image
// times rm_DeltaTime to what it held after the last frame, so every output says exactly which
// frames ran before it and at which step.

namespace rmfx::test {

inline constexpr const char* kAccumulateWorkspace = R"(<workspace version="1" name="accumulate" size="5x3">
  <target name="sum" format="rgba32f"/>
  <input name="frame"/>
  <pass name="accumulate" target="sum">
    <sampler name="Previous" target="sum" frame="previous" filter="nearest"/>
    <sampler name="Frame" texture="frame" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Previous;
uniform sampler2D Frame;
uniform float rm_DeltaTime;
out vec4 c;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    c = texelFetch(Previous, p, 0) + texelFetch(Frame, p, 0) * rm_DeltaTime;
}
]]></shader>
  </pass>
  <output target="sum" transform="none"/>
</workspace>
)";

}  // namespace rmfx::test

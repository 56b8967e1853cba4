"""The module's own behaviour: orientation, values and their maths, reading a workspace, errors."""
import gc
import pickle

import numpy as np
import pytest

import rmfx
from conftest import SOURCE_DIR

SHADER_1 = SOURCE_DIR / "effects" / "shader_1.xml"  # output = the scene input × Exposure_Level, alpha 1, rgba16f


def gradient(height=16, width=8):
    """Rows from 0 at the top to 15/16 at the bottom (exact in half floats): top and bottom differ."""
    rows = (np.arange(height, dtype=np.float32) / height)[:, None]
    image = np.zeros((height, width, 4), np.float32)
    image[..., 0] = rows
    image[..., 1] = 1.0 - rows
    image[..., 2] = (np.arange(width, dtype=np.float32) / width)[None, :]
    image[..., 3] = 1.0
    return image


def test_row_0_is_the_top():
    scene = gradient()
    out = rmfx.load(SHADER_1).renderer().render(inputs={"scene": scene})
    assert out.dtype == np.float32 and out.shape == (16, 8, 4)  # the input's size: height 16, width 8
    assert out[0, 0, 0] == 0.0 and out[-1, 0, 0] == pytest.approx(0.5 * 15 / 16)
    np.testing.assert_array_equal(out[..., :3], scene[..., :3] * 0.5)  # Exposure_Level's default, 0.5


def test_setting_a_variable_scales_the_output():
    ws = rmfx.load(SHADER_1)
    assert ws["Exposure_Level"] == 0.5
    renderer = ws.renderer()
    scene = gradient()
    half = renderer.render(inputs={"scene": scene})
    ws["Exposure_Level"] = 2.0
    assert ws["Exposure_Level"] == 2.0
    double = renderer.render(inputs={"scene": scene})
    np.testing.assert_array_equal(double[..., :3], scene[..., :3] * 2.0)
    np.testing.assert_array_equal(double[..., :3], half[..., :3] * 4.0)
    np.testing.assert_array_equal(double[..., 3], 1.0)
    # A new image on the kept executor, and the same through a fresh renderer.
    flipped = scene[::-1]
    np.testing.assert_array_equal(renderer.render(inputs={"scene": flipped})[..., :3], flipped[..., :3] * 2.0)
    np.testing.assert_array_equal(ws.renderer().render(inputs={"scene": flipped}), renderer.render(inputs={"scene": flipped}))


def test_input_types():
    scene = gradient()
    renderer = rmfx.load(SHADER_1, Exposure_Level=1).renderer()
    exact = renderer.render(inputs={"scene": scene})
    np.testing.assert_array_equal(exact[..., :3], scene[..., :3])
    np.testing.assert_array_equal(renderer.render(inputs={"scene": scene.astype(np.float16)}), exact)
    np.testing.assert_array_equal(renderer.render(inputs={"scene": scene[..., :3].copy()}), exact)  # alpha 1
    np.testing.assert_array_equal(renderer.render(inputs={"scene": np.asfortranarray(scene)}), exact)
    # An array that crossed a process (Dask, multiprocessing) has a dtype equal to float32 but not the same object.
    np.testing.assert_array_equal(renderer.render(inputs={"scene": pickle.loads(pickle.dumps(scene))}), exact)
    np.testing.assert_array_equal(renderer.render(inputs={"scene": scene.astype("<f4")}), exact)
    with pytest.raises(rmfx.Error):
        renderer.render(inputs={"scene": scene.astype(">f4")})  # big-endian: not what the GPU takes
    # uint8 is sRGB: 255 is 1, 0 is 0, 188 is 0.50289 linear, which the 8-bit texture an 8-bit image
    # goes into (as rmfx render puts an 8-bit PNG) holds as 128 / 255; the rgba16f output as a half.
    srgb = np.zeros((16, 8, 3), np.uint8)
    srgb[:8] = 255
    srgb[8:, :, 1] = 188
    out = renderer.render(inputs={"scene": srgb})
    np.testing.assert_array_equal(out[:8, :, :3], 1.0)
    np.testing.assert_array_equal(out[8:, :, 1], np.float32(np.float16(128 / 255)))
    np.testing.assert_array_equal(out[8:, :, 0], 0.0)


def test_workspace_is_read():
    ws = rmfx.load(SHADER_1)
    assert ws.name == "shader_1" and ws.size == (512, 512) and ws.inputs == ["scene"] and ws.output == "output"
    exposure = ws.variable("Exposure_Level")
    assert (exposure.type, exposure.value, exposure.range, exposure.widget) == ("float", 0.5, (0.0, 4.0), "slider")
    assert exposure.step == pytest.approx(0.01)  # a float32
    assert exposure.line == 10 and exposure.file.endswith("shader_1.xml")
    fmt = ws.variable("Environment_Format")
    assert fmt.type == "int" and fmt.options == ["8-bit alpha x64", "half float"]
    assert [v.name for v in ws.variables][:2] == ["Exposure_Level", "Environment_Format"]
    hdr = rmfx.load(SOURCE_DIR / "effects" / "hdr_lighting.xml")
    assert hdr.effects and all(e.selected for e in hdr.effects)
    first = hdr.effects[0].name
    hdr.effects_selected = [first]
    assert [e.name for e in hdr.effects if e.selected] == [first]
    with pytest.raises(rmfx.Error):
        hdr.effects_selected = ["no_such_effect"]
    assert hdr.effects_selected == [first]


def test_explain_timings_and_check():
    ws = rmfx.load(SHADER_1)
    before = ws.renderer(size=(32, 32)).explain()
    assert "screen" in before
    renderer = ws.renderer(size=(32, 32), timing=True)
    renderer.render(frames=2)
    assert "screen" in renderer.explain()
    assert [t.name for t in renderer.timings] == renderer.passes_run and all(t.milliseconds >= 0 for t in renderer.timings)
    # A NaN in the input: the effect sanitises it, so the check finds nothing in its targets.
    scene = gradient()
    scene[0, 0, 0] = np.nan
    renderer.render(inputs={"scene": scene}, check=True)
    assert all(isinstance(f, rmfx.HealthFinding) for f in renderer.findings)


def raises(call, *, file=None, line=None, element=None):
    with pytest.raises(rmfx.Error) as caught:
        call()
    error = caught.value
    if file is not None:
        assert error.file is not None and error.file.endswith(file), (error.file, str(error))
    if line is not None:
        assert error.line == line, (error.line, str(error))
    if element is not None:
        assert error.element is not None and element in error.element, (error.element, str(error))
    assert error.diagnostics and str(error)
    return error


def test_hostile_input_raises_rmfx_error(tmp_path):
    raises(lambda: rmfx.load(tmp_path / "missing.xml"), file="missing.xml")
    broken = tmp_path / "broken.xml"
    broken.write_text('<?xml version="1.0"?>\n<workspace version="1" name="b">\n  <float name="x" value="abc"/>\n</workspace>\n')
    raises(lambda: rmfx.load(broken), file="broken.xml", line=3)
    unclosed = tmp_path / "unclosed.xml"
    unclosed.write_text('<?xml version="1.0"?>\n<workspace version="1" name="b">\n  <float name="x"\n')
    raises(lambda: rmfx.load(unclosed), file="unclosed.xml")
    raises(lambda: rmfx.load(SHADER_1, missing_media="maybe"), element="missing_media")
    raises(lambda: rmfx.load(SHADER_1, No_Such=1), element="No_Such")
    raises(lambda: rmfx.load(SHADER_1, Exposure_Level="bright"), file="shader_1.xml", line=10, element="Exposure_Level")

    ws = rmfx.load(SHADER_1)
    raises(lambda: ws["No_Such"], element="No_Such")
    raises(lambda: ws.__setitem__("No_Such", 1.0), element="No_Such")
    raises(lambda: ws.__setitem__("Exposure_Level", "bright"), file="shader_1.xml", line=10)
    raises(lambda: ws.__setitem__("Exposure_Level", (1.0, 2.0)), file="shader_1.xml", line=10)
    raises(lambda: ws.__setitem__("Environment_Format", 0.5), file="shader_1.xml", line=12)
    raises(lambda: ws.__setitem__("Exposure_Level", {"a": 1}), element="Exposure_Level")
    ws["Exposure_Level"] = np.array(0.5)  # a 0-d array is a number
    ws["Exposure_Level"] = np.float32(0.5)
    assert ws["Exposure_Level"] == 0.5 and ws["Environment_Format"] == 0  # unchanged by the failures

    renderer = ws.renderer(size=(8, 8))
    for bad in (np.zeros((8, 8, 4), np.float64), np.zeros((8, 8), np.float32), np.zeros((8, 8, 2), np.float32),
                np.zeros((0, 8, 4), np.float32), np.zeros((8, 8, 4), np.int32), [[0.0] * 4] * 8, 42, None):
        raises(lambda: renderer.render(inputs={"scene": bad}), element="scene")
    raises(lambda: renderer.render(inputs={"nope": gradient()}), element="nope")
    raises(lambda: renderer.render(inputs={"scene": tmp_path / "missing.exr"}), element="scene")
    (tmp_path / "garbage.exr").write_bytes(b"not an image at all")
    raises(lambda: renderer.render(inputs={"scene": tmp_path / "garbage.exr"}), element="scene")
    raises(lambda: renderer.render(target="no_such_target"), element="target")
    raises(lambda: renderer.render(frames=0), element="frames")
    raises(lambda: ws.renderer(size=(-1, 5)), element="size")
    raises(lambda: rmfx.Renderer(None), element="workspace")
    raises(lambda: renderer.render(dt=float("nan")), element="dt")
    raises(lambda: rmfx.load(tmp_path), file=tmp_path.name)  # a folder
    (tmp_path / "junk.rfx").write_bytes(bytes(range(256)) * 8)
    raises(lambda: rmfx.load(tmp_path / "junk.rfx"), file="junk.rfx")
    bad_shader = tmp_path / "bad_shader.xml"
    (tmp_path / "bad.frag").write_text("void main() { this is not glsl }\n")
    bad_shader.write_text('<?xml version="1.0"?>\n<workspace version="1" name="b">\n  <pass name="p">\n'
                          '    <shader stage="fragment" file="bad.frag"/>\n  </pass>\n</workspace>\n')
    raises(lambda: rmfx.load(bad_shader), file="bad.frag", line=1, element="pass")
    # After all that the renderer still renders.
    assert renderer.render(inputs={"scene": gradient(8, 8)}).shape == (8, 8, 4)


def test_renderers_share_a_thread_and_die_in_any_order():
    a = rmfx.load(SHADER_1).renderer(size=(8, 8))
    b = rmfx.load(SHADER_1, Exposure_Level=1.0).renderer(size=(8, 8))
    scene = gradient(8, 8)
    out_a = a.render(inputs={"scene": scene})
    out_b = b.render(inputs={"scene": scene})
    np.testing.assert_array_equal(out_a[..., :3] * 2, out_b[..., :3])
    del a
    gc.collect()
    np.testing.assert_array_equal(b.render(inputs={"scene": scene}), out_b)


FORMATS = """<?xml version="1.0"?>
<workspace version="1" name="formats" size="3x2">
  <target name="bytes" format="rgba8"/>
  <target name="shorts" format="rgba16"/>
  <target name="halves" format="r16f"/>
  <target name="floats" format="rgba32f"/>
  {passes}
  <output target="floats" transform="none"/>
</workspace>
"""
PASS = """<pass name="{t}" target="{t}"><shader stage="fragment"><![CDATA[
out vec4 c;
// Row 0 of the image (the top) is 0.2 in red, the bottom row 0.8; green 0.6, blue 1, alpha 0.
void main() {{ c = vec4(gl_FragCoord.y < 1.0 ? 0.8 : 0.2, 0.6, 1.0, 0.0); }}
]]></shader></pass>"""


def test_dtype_target_gives_the_targets_own_type(tmp_path):
    path = tmp_path / "formats.xml"
    path.write_text(FORMATS.format(passes="\n  ".join(PASS.format(t=t) for t in ("bytes", "shorts", "halves", "floats"))))
    renderer = rmfx.load(path).renderer()
    expected = np.array([[0.2, 0.6, 1.0, 0.0]] * 3 + [[0.8, 0.6, 1.0, 0.0]] * 3).reshape(2, 3, 4)
    as_bytes = renderer.render(target="bytes", dtype="target")
    assert as_bytes.dtype == np.uint8 and as_bytes.shape == (2, 3, 4)
    np.testing.assert_array_equal(as_bytes, np.rint(expected * 255).astype(np.uint8))  # 51, 153, 255, 0 over 204, …
    shorts = renderer.render(target="shorts", dtype="target")
    assert shorts.dtype == np.uint16
    np.testing.assert_array_equal(shorts, np.rint(expected * 65535).astype(np.uint16))
    halves = renderer.render(target="halves", dtype="target")
    assert halves.dtype == np.float16 and halves.shape == (2, 3, 1)
    np.testing.assert_array_equal(halves[..., 0], expected[..., 0].astype(np.float16))
    floats = renderer.render(target="floats", dtype="target")
    assert floats.dtype == np.float32
    np.testing.assert_array_equal(floats, expected.astype(np.float32))
    # As float32: byte / 255 (as the driver divides: to within an ulp).
    np.testing.assert_allclose(renderer.render(target="bytes"), np.rint(expected * 255) / 255, rtol=2e-7, atol=0)
    with pytest.raises(rmfx.Error) as e:
        renderer.render(dtype="int8")
    assert e.value.element == "dtype"
    frames = list(rmfx.load(SHADER_1).renderer().sequence([gradient()] * 2, dtype="target"))
    assert frames[1].dtype == np.float16  # shader_1's output is rgba16f
    np.testing.assert_array_equal(frames[1][..., :3], (gradient()[..., :3] * 0.5).astype(np.float16))


def test_arrays_written_in_place_equal_a_fresh_run():
    """After the first render, a float32 or float16 RGBA array goes to the GPU from its own memory
    (no copy): rows apart (a crop of a larger image), turned top to bottom, halves; each must give
    what a renderer built for that image gives, which converts it the other way."""
    renderer = rmfx.load(SHADER_1, Exposure_Level=1).renderer()
    first = gradient()
    np.testing.assert_array_equal(renderer.render(inputs={"scene": first})[..., :3], first[..., :3])
    large = np.zeros((40, 30, 4), np.float32)
    large[5:21, 7:15] = gradient()[::-1] * 0.75
    crop = large[5:21, 7:15]  # rows 30 pixels apart
    assert not crop.flags.c_contiguous
    halves = (gradient() * 0.5).astype(np.float16)
    for image in (crop, halves, np.ascontiguousarray(first[:, ::-1])):
        kept = renderer.render(inputs={"scene": image})
        fresh = rmfx.load(SHADER_1, Exposure_Level=1).renderer().render(inputs={"scene": np.array(image, np.float32)})
        np.testing.assert_array_equal(kept, fresh)
        np.testing.assert_array_equal(kept[..., :3], np.asarray(image, np.float32)[..., :3])

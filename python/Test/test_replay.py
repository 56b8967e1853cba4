"""rmfx.replay: a manifest's cases run in this process, their compares as objects with the errors
measured; checked against errors computed here from the images (NumPy, not rmfx)."""
import numpy as np
import pytest

import rmfx
from conftest import SOURCE_DIR

pytest.importorskip("OpenImageIO", reason="python3-openimageio writes the case's input and reference (scripts/setup.sh)")
from images import read_exr, write_exr  # noqa: E402

SHADER_1 = SOURCE_DIR / "effects" / "shader_1.xml"  # output = the scene input × Exposure_Level, alpha 1, rgba16f


def manifest(folder, exposure="0.5", extra=""):
    text = f"""<?xml version="1.0" encoding="UTF-8"?>
<replay version="1">
  <media dir="{SOURCE_DIR / 'samples' / 'media'}"/>
  <defaults size="16x8" frames="1" max="0"/>
  <case name="scaled" workspace="{SHADER_1}">
    <set name="Exposure_Level" value="{exposure}"/>
    <input name="scene" file="scene.exr"/>
    <compare reference="refs/scaled.exr"/>
  </case>
  <case name="plain" workspace="{SHADER_1}">
    <input name="scene" file="scene.exr"/>
    <compare reference="refs/plain.exr"/>
  </case>{extra}
</replay>
"""
    path = folder / "manifest.xml"
    path.write_text(text)
    return path


def scene():
    """Rows 0 … 7/8 top to bottom in red, columns in blue: exact in half floats, asymmetric."""
    image = np.zeros((8, 16, 4), np.float32)
    image[..., 0] = (np.arange(8, dtype=np.float32) / 8)[:, None]
    image[..., 2] = (np.arange(16, dtype=np.float32) / 16)[None, :]
    image[..., 3] = 1.0
    return image


def test_update_then_replay_passes_and_a_change_fails_with_its_error(tmp_path):
    write_exr(tmp_path / "scene.exr", scene())
    path = manifest(tmp_path)
    assert rmfx.replay_cases(path) == ["scaled", "plain"]
    stored = rmfx.replay(path, update=True)
    assert stored.passed and [c.status for c in stored.cases] == ["updated", "updated"]
    reference = read_exr(tmp_path / "refs" / "scaled.exr")
    np.testing.assert_array_equal(reference[..., :3], scene()[..., :3] * 0.5)
    assert reference[0, 15, 2] == pytest.approx(0.5 * 15 / 16) and reference[7, 0, 0] == pytest.approx(0.5 * 7 / 8)

    report = rmfx.replay(path)
    assert report.passed and all(c.passed for c in report.cases), [c.description for c in report.cases]
    compare = report["scaled"].compares[0]
    assert (compare.label, compare.max_error, compare.passed) == ("output", 0.0, True)
    np.testing.assert_array_equal(compare.actual, reference)

    # Exposure 0.75 against the 0.5 reference: the largest error is 0.25 × the largest input, 7/8
    # red at the bottom row (or 15/16 blue at the right): 0.25 · 15/16, at the rightmost column.
    changed = rmfx.replay(manifest(tmp_path, exposure="0.75"))
    assert not changed.passed
    case = changed["scaled"]
    assert case.status == "failed" and not case.passed and "FAILED" in case.description
    compare = case.compares[0]
    assert compare.max_error == pytest.approx(0.25 * 15 / 16)
    assert compare.max_error_at == (15, 0, 2)  # row 0 at the top: every row holds the rightmost blue
    expected_mean = np.abs(scene()[..., :3] * 0.25).sum() / (8 * 16 * 4)
    assert compare.mean_error == pytest.approx(expected_mean, rel=1e-6)
    assert [check[0] for check in compare.checks] == ["max error"] and compare.checks[0][3] is False
    assert compare.difference.shape[:2] == (8, 16)
    assert changed["plain"].passed  # the other case still runs and passes


def test_errors_are_cases_or_raised(tmp_path):
    write_exr(tmp_path / "scene.exr", scene())
    broken = '\n  <case name="broken" workspace="missing.xml">\n    <compare reference="refs/b.exr"/>\n  </case>'
    path = manifest(tmp_path, extra=broken)
    rmfx.replay(path, cases=["plain"], update=True)
    report = rmfx.replay(path, cases=["plain", "broken"])
    assert [c.status for c in report.cases] == ["passed", "error"]
    assert any(d.file and d.file.endswith("missing.xml") for d in report["broken"].diagnostics)
    with pytest.raises(rmfx.Error) as e:
        rmfx.replay(path, cases=["nope"])
    assert e.value.element == "case nope"
    (tmp_path / "bad.xml").write_text('<?xml version="1.0"?>\n<replay version="1">\n  <case name="x"/>\n</replay>\n')
    with pytest.raises(rmfx.Error) as e:
        rmfx.replay(tmp_path / "bad.xml")
    assert e.value.file.endswith("bad.xml") and e.value.line == 3
    with pytest.raises(rmfx.Error):
        rmfx.replay(tmp_path / "absent.xml")

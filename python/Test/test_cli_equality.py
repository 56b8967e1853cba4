"""The module renders what `rmfx render` renders, bit for bit, for every workspace in effects/.

Each workspace is rendered at 64x64 by the command into a float EXR (read back with OpenImageIO's
own Python binding, independent of rmfx) and by the module into an array; the two must hold the
same 32-bit patterns in every channel (NaN included)."""
import subprocess

import numpy as np
import pytest

import rmfx
from conftest import SOURCE_DIR

pytest.importorskip("OpenImageIO", reason="python3-openimageio reads the command's EXR (scripts/setup.sh)")
from images import assert_bit_equal, read_exr, write_exr  # noqa: E402

WORKSPACES = sorted((SOURCE_DIR / "effects").glob("*.xml")) + sorted((SOURCE_DIR / "effects" / "variants").glob("*.xml"))
SIZE = (64, 64)


def cli_render(rmfx_binary, workspace, out, *args):
    command = [str(rmfx_binary), "render", str(workspace), "--size", f"{SIZE[0]}x{SIZE[1]}", "-q", "-o", str(out), *args]
    done = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, f"{' '.join(command)}\n{done.stderr}"
    return read_exr(out)


def test_every_effect_is_covered():
    assert len(WORKSPACES) >= 10, WORKSPACES


@pytest.mark.parametrize("workspace", WORKSPACES, ids=lambda p: p.relative_to(SOURCE_DIR / "effects").as_posix())
def test_module_equals_cli(workspace, rmfx_binary, tmp_path):
    cli = cli_render(rmfx_binary, workspace, tmp_path / "cli.exr")
    module = rmfx.load(workspace).renderer(size=SIZE).render()
    assert module.ndim == 3 and module.shape[2] == 4  # the output's size: a workspace may scale it
    assert_bit_equal(module, cli)


def test_module_equals_cli_with_values_frames_and_an_input(rmfx_binary, tmp_path):
    """--set, --frames, --dt and --input scene=FILE against the same through the module."""
    rows = np.linspace(0.0, 4.0, SIZE[1], dtype=np.float32)[:, None, None]
    cols = np.linspace(0.0, 1.0, SIZE[0], dtype=np.float32)[None, :, None]
    scene = np.concatenate([rows * cols + 0.01, np.broadcast_to(rows, (SIZE[1], SIZE[0], 1)),
                            np.full((SIZE[1], SIZE[0], 1), 0.5, np.float32)], axis=2).astype(np.float32)
    write_exr(tmp_path / "scene.exr", scene)
    workspace = SOURCE_DIR / "effects" / "auto_exposure.xml"
    cli = cli_render(rmfx_binary, workspace, tmp_path / "cli.exr", "--input", f"scene={tmp_path / 'scene.exr'}",
                     "--frames", "3", "--dt", "0.05")
    ws = rmfx.load(workspace)
    renderer = ws.renderer(size=SIZE)
    assert_bit_equal(renderer.render(inputs={"scene": scene}, frames=3, dt=0.05), cli)
    # A path gives the same as the array it holds.
    renderer.reset()
    assert_bit_equal(renderer.render(inputs={"scene": tmp_path / "scene.exr"}, frames=3, dt=0.05), cli)

    shader_1 = SOURCE_DIR / "effects" / "shader_1.xml"
    cli = cli_render(rmfx_binary, shader_1, tmp_path / "cli1.exr", "--set", "Exposure_Level=1.75", "--set", "Environment_Format=1")
    assert_bit_equal(rmfx.load(shader_1, Exposure_Level=1.75, Environment_Format=1).renderer(size=SIZE).render(), cli)
    # Set after loading, on a renderer that has rendered already (its executor kept, the values set on it).
    ws = rmfx.load(shader_1)
    renderer = ws.renderer(size=SIZE)
    renderer.render()
    ws["Exposure_Level"] = 1.75
    ws["Environment_Format"] = 1
    assert_bit_equal(renderer.render(), cli)


def test_textures_and_sandbox_as_the_command_takes_them(rmfx_binary, tmp_path):
    """rmfx.load(textures={...}) is --texture, and survives pickling; sandbox=True is --sandbox."""
    import pickle

    rows = np.linspace(0.0, 3.0, 32, dtype=np.float32)[:, None, None]  # a 2:1 longitude/latitude sky, top bright
    cols = np.linspace(0.2, 1.0, 64, dtype=np.float32)[None, :, None]
    sky = np.concatenate([np.broadcast_to(3.0 - rows, (32, 64, 1)), np.broadcast_to(cols, (32, 64, 1)),
                          np.broadcast_to(rows * cols, (32, 64, 1))], axis=2).astype(np.float32)
    write_exr(tmp_path / "sky.exr", sky)
    shader_1 = SOURCE_DIR / "effects" / "shader_1.xml"
    cli = cli_render(rmfx_binary, shader_1, tmp_path / "cli.exr", "--texture", f"Sky_Float={tmp_path / 'sky.exr'}",
                     "--set", "Environment_Format=1")
    ws = rmfx.load(shader_1, textures={"Sky_Float": tmp_path / "sky.exr"}, Environment_Format=1)
    assert_bit_equal(ws.renderer(size=SIZE).render(), cli)
    assert_bit_equal(pickle.loads(pickle.dumps(ws)).renderer(size=SIZE).render(), cli)
    assert not np.array_equal(rmfx.load(shader_1, Environment_Format=1).renderer(size=SIZE).render(), cli)

    with pytest.raises(rmfx.Error) as e:
        rmfx.load(shader_1, sandbox=True)
    assert "sandbox" in str(e.value) and e.value.file.endswith("shader_1.xml")
    rmfx.load(shader_1, sandbox=True, media=[SOURCE_DIR / "samples" / "media"])
    with pytest.raises(rmfx.Error) as e:
        rmfx.load(shader_1, textures={"Sky_Float": 42})
    assert e.value.element == "texture Sky_Float"
    with pytest.raises(rmfx.Error):
        rmfx.load(shader_1, textures={"No_Such_Texture": tmp_path / "sky.exr"})


def test_run_options_as_the_command_takes_them(rmfx_binary, tmp_path):
    """memory_budget is --memory-budget (a run over it fails before anything renders); content_skip=False
    and pool_targets=False are --content-skip off and --no-pool, which change no pixel."""
    hdr = SOURCE_DIR / "effects" / "hdr_lighting.xml"
    dark = np.full((SIZE[1], SIZE[0], 4), 0.01, np.float32)  # nothing for the bright pass: content skip skips bloom
    write_exr(tmp_path / "dark.exr", dark)
    cli = cli_render(rmfx_binary, hdr, tmp_path / "cli.exr", "--input", f"scene={tmp_path / 'dark.exr'}", "--frames", "2",
                     "--content-skip", "off", "--no-pool")
    ws = rmfx.load(hdr)
    for options in ({}, {"content_skip": False}, {"pool_targets": False}, {"content_skip": False, "pool_targets": False}):
        assert_bit_equal(ws.renderer(size=SIZE, **options).render(inputs={"scene": dark}, frames=2), cli)
    with pytest.raises(rmfx.Error) as e:
        ws.renderer(size=SIZE, memory_budget=0.01).render(inputs={"scene": dark})
    assert "memory" in str(e.value)
    with pytest.raises(rmfx.Error) as e:
        ws.renderer(memory_budget=-1)
    assert e.value.element == "memory_budget"

"""Shots through the module: Renderer.sequence against rmfx render's own sequences (whole, and a
chunk with --frame-range), bit for bit; and rmfx.dask over a LocalCluster of two worker processes
against one run: bit for bit without frame-to-frame state, and within the bound docs/sequences.md
states for hdr_lighting's light adaptation with it."""
import subprocess

import numpy as np
import pytest

import rmfx
from conftest import SOURCE_DIR

pytest.importorskip("OpenImageIO", reason="python3-openimageio writes the command's input frames (scripts/setup.sh)")
from images import assert_bit_equal, read_exr, write_exr  # noqa: E402

HDR_LIGHTING = SOURCE_DIR / "effects" / "hdr_lighting.xml"


def shot(count, size=32):
    """A brightening shot: frame k is a vertical ramp (top dark, bottom bright, left and right differ)
    with a hot spot at the top left that grows with k, so every frame measures a new luminance and
    the bright pass has something to find."""
    rows = np.linspace(0.02, 0.2, size, dtype=np.float32)[:, None]
    cols = np.linspace(0.5, 1.0, size, dtype=np.float32)[None, :]
    frames = []
    for k in range(count):
        image = np.zeros((size, size, 4), np.float32)
        image[..., 0] = rows * cols * (1 + 0.15 * k)
        image[..., 1] = rows * (1 + 0.1 * k)
        image[..., 2] = cols * 0.05
        image[..., 3] = 1.0
        image[2:5, 2:6, :3] = 4.0 + k
        frames.append(image)
    return frames


def cli_sequence(rmfx_binary, folder, *args):
    command = [str(rmfx_binary), "render", str(HDR_LIGHTING), "--input", f"scene={folder / 'f.%04d.exr'}", "-q",
               "-o", str(folder / "out.%04d.exr"), *args]
    done = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, f"{' '.join(command)}\n{done.stderr}"


def test_sequence_equals_the_commands_sequence_and_chunk(rmfx_binary, tmp_path):
    frames = shot(6)
    for k, image in enumerate(frames):
        write_exr(tmp_path / f"f.{k + 1:04d}.exr", image)
    cli_sequence(rmfx_binary, tmp_path, "--fps", "24", "--preroll", "3")
    cli = [read_exr(tmp_path / f"out.{k + 1:04d}.exr") for k in range(6)]
    renderer = rmfx.load(HDR_LIGHTING).renderer()
    arrays = list(renderer.sequence(frames, preroll=3))
    assert len(arrays) == 6
    for k in range(6):
        assert_bit_equal(arrays[k], cli[k])
    # Paths give the same; a sequence started again starts from the initial state.
    paths = list(renderer.sequence([tmp_path / f"f.{k + 1:04d}.exr" for k in range(6)], preroll=3))
    for k in range(6):
        assert_bit_equal(paths[k], cli[k])

    # The chunk 4-6 with --frame-range, and the same through start, preroll and skip.
    for k in range(6):
        (tmp_path / f"out.{k + 1:04d}.exr").unlink()
    cli_sequence(rmfx_binary, tmp_path, "--fps", "24", "--preroll", "2", "--frame-range", "4-6")
    assert not (tmp_path / "out.0003.exr").exists()
    chunk = rmfx.sequence_chunk(3, 2)
    assert (chunk.start, chunk.preroll, chunk.skip) == (1, 0, 2)
    arrays = list(renderer.sequence(frames[chunk.start:], start=chunk.start, preroll=chunk.preroll, skip=chunk.skip))
    assert len(arrays) == 3
    for k in range(3):
        assert_bit_equal(arrays[k], read_exr(tmp_path / f"out.{k + 4:04d}.exr"))


def test_sequence_arguments_are_checked():
    renderer = rmfx.load(HDR_LIGHTING).renderer()
    frames = shot(2, 8)
    with pytest.raises(rmfx.Error) as e:
        renderer.sequence(frames, input="nope")
    assert "nope" in e.value.element
    with pytest.raises(rmfx.Error) as e:
        renderer.sequence(frames, dt=0.1, fps=10)
    assert e.value.element == "fps"
    with pytest.raises(rmfx.Error):
        renderer.sequence(frames, skip=-1)
    with pytest.raises(rmfx.Error):
        list(renderer.sequence(frames, preroll=-2))
    with pytest.raises(rmfx.Error) as e:
        list(renderer.sequence([frames[0], np.zeros((8, 8), np.float32)]))
    assert "scene" in e.value.element
    assert list(renderer.sequence([])) == []
    with pytest.raises(rmfx.Error):
        rmfx.sequence_chunk(-1, 3)


ADAPTATION_PER_SECOND = 0.98 ** 30  # hdr_adapt.frag: the part of the gap that remains after one second


def test_dask_two_workers_equal_one_run():
    distributed = pytest.importorskip("distributed", reason="python3-distributed runs the cluster (scripts/setup.sh)")
    import rmfx.dask

    frames = shot(24)
    dt, preroll, chunk = 1 / 24, 6, 12
    stateless = rmfx.load(HDR_LIGHTING, Light_Adaptation=False)  # adapted = measured each frame: no state
    stateful = rmfx.load(HDR_LIGHTING)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        split = rmfx.dask.render_sequence(client, stateless, frames, chunk=chunk, preroll=preroll)
        split_adapted = rmfx.dask.render_sequence(client, stateful, frames, chunk=chunk, preroll=preroll, target="adapted")
        split_stateful = rmfx.dask.render_sequence(client, stateful, frames, chunk=chunk, preroll=preroll)
        # An error on a worker arrives whole, with its element.
        with pytest.raises(rmfx.Error) as e:
            rmfx.dask.render_sequence(client, stateful, frames[:2] + [np.zeros((3, 3), np.float32)], chunk=2)
        assert "scene" in e.value.element
        # Names and chunking are checked before any task is sent.
        for bad in (dict(input="nope"), dict(chunk=0), dict(preroll=-1), dict(dt=0.1, fps=10)):
            with pytest.raises(rmfx.Error):
                rmfx.dask.render_sequence(client, stateful, frames, **bad)
    whole = list(stateless.renderer().sequence(frames, preroll=preroll))
    assert len(split) == len(whole) == 24
    for k in range(24):
        assert_bit_equal(split[k], whole[k])

    # With adaptation: the first chunk is the whole run's beginning, bit for bit; the second starts
    # from the initial 1.0 six frames before frame 12, where the whole run had adapted to a_w, so
    # the two differ by |1 - a_w| 0.98^(30 dt n) after n frames (docs/sequences.md).
    whole_adapted = [a[0, 0, 0] for a in stateful.renderer().sequence(frames, preroll=preroll, target="adapted")]
    whole_stateful = list(stateful.renderer().sequence(frames, preroll=preroll))
    for k in range(chunk):
        assert split_adapted[k][0, 0, 0] == whole_adapted[k]
        assert_bit_equal(split_stateful[k], whole_stateful[k])
    before = whole_adapted[chunk - preroll - 1]
    for k in range(chunk, 24):
        n = k - (chunk - preroll) + 1
        bound = abs(1.0 - before) * ADAPTATION_PER_SECOND ** (dt * n)
        difference = abs(float(split_adapted[k][0, 0, 0]) - float(whole_adapted[k]))
        assert difference <= bound * (1 + 1e-4) + 2e-6, (k, difference, bound)
        assert difference >= bound * (1 - 1e-3) - 2e-6, (k, difference, bound)  # the bound is what happens
        # The image follows the state: its relative difference stays within the adapted luminance's
        # (the tone map's exposure is key / (adapted + 0.001); docs/sequences.md shows the figures).
        relative = np.abs(split_stateful[k][..., :3] - whole_stateful[k][..., :3]) / np.abs(whole_stateful[k][..., :3])
        assert np.isfinite(split_stateful[k]).all() and relative.max() <= difference / whole_adapted[k] + 1e-5, k

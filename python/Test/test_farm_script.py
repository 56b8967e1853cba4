"""samples/farm/render-chunk.sh, the body of a render-farm task (a Slurm array task), run for each
task number as the farm would: the chunks together equal one rmfx render of the whole shot, bit for
bit, for an effect without frame-to-frame state (hdr_lighting with its adaptation off)."""
import os
import subprocess

import pytest

from conftest import SOURCE_DIR

pytest.importorskip("OpenImageIO", reason="python3-openimageio writes the shot (scripts/setup.sh)")
from images import assert_bit_equal, read_exr, write_exr  # noqa: E402
from test_sequences import HDR_LIGHTING, shot  # noqa: E402

SCRIPT = SOURCE_DIR / "samples" / "farm" / "render-chunk.sh"


def test_chunks_from_the_farm_script_equal_the_whole_run(rmfx_binary, tmp_path):
    for k, image in enumerate(shot(5, 16)):
        write_exr(tmp_path / f"beauty.{1001 + k:04d}.exr", image)
    whole = subprocess.run([str(rmfx_binary), "render", str(HDR_LIGHTING), "--input", str(tmp_path / "beauty.%04d.exr"),
                            "--preroll", "3", "--set", "Light_Adaptation=false", "-q", "-o", str(tmp_path / "whole.%04d.exr")],
                           capture_output=True, text=True, timeout=300)
    assert whole.returncode == 0, whole.stderr
    environment = dict(os.environ, RMFX=str(rmfx_binary), WORKSPACE=str(HDR_LIGHTING), INPUT=str(tmp_path / "beauty.%04d.exr"),
                       OUTPUT=str(tmp_path / "farm.%04d.exr"), FIRST="1001", LAST="1005", CHUNK="2", PREROLL="3")
    logs = []
    for task in range(4):  # the last has nothing to do
        done = subprocess.run([str(SCRIPT), "--set", "Light_Adaptation=false", "-q"], env=dict(environment, SLURM_ARRAY_TASK_ID=str(task)),
                              capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stdout + done.stderr
        logs.append(done.stdout)
    assert "task 1: frames 1003-1004 of 1001-1005, 3 frames of warm-up" in logs[1]
    assert "task 3: nothing to render" in logs[3]
    for frame in range(1001, 1006):
        assert_bit_equal(read_exr(tmp_path / f"farm.{frame:04d}.exr"), read_exr(tmp_path / f"whole.{frame:04d}.exr"))
    missing = subprocess.run([str(SCRIPT)], env=dict(environment, SLURM_ARRAY_TASK_ID="0", WORKSPACE=""),
                             capture_output=True, text=True, timeout=60)
    assert missing.returncode != 0 and "WORKSPACE" in missing.stderr

#!/usr/bin/python3
"""What Python adds to a frame: hdr_lighting at 512x512, one frame at a time with a NumPy array in
and a NumPy array out (Renderer.render), against the same renderer's executor driven by a C++ loop
that gives the same image and reads the same target back (Renderer._cpp_frame_loop). Rounds of
the two alternate in one process, so that the machine's load falls on both alike; the figure is
the ratio of the medians. The issue's target: at most 1.05.

    PYTHONPATH=build/python bench/python-overhead.py [--rounds 7] [--frames 10] [--size 512]
"""
import argparse
import os
import pathlib
import statistics
import sys
import time

import numpy as np

import rmfx

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[1]


def scene(size):
    """An HDR image with a bright patch at the top left: rows and columns differ."""
    y = np.linspace(0.05, 1.0, size, dtype=np.float32)[:, None]
    x = np.linspace(0.2, 0.8, size, dtype=np.float32)[None, :]
    image = np.empty((size, size, 4), np.float32)
    image[..., 0] = y * x
    image[..., 1] = y
    image[..., 2] = x * 0.5
    image[..., 3] = 1.0
    image[size // 16:size // 8, size // 16:size // 8, :3] = 20.0
    return image


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--frames", type=int, default=10, help="frames per round and side")
    parser.add_argument("--size", type=int, default=512)
    args = parser.parse_args()

    image = scene(args.size)
    renderer = rmfx.load(SOURCE_DIR / "effects" / "hdr_lighting.xml").renderer()
    inputs = {"scene": image}
    for _ in range(5):  # warm-up: the run built, shaders compiled, caches filled
        renderer.render(inputs=inputs)
    python, cpp = [], []
    for _ in range(args.rounds):
        for _ in range(args.frames):
            start = time.perf_counter()
            out = renderer.render(inputs=inputs)
            python.append(time.perf_counter() - start)
        cpp.extend(renderer._cpp_frame_loop(inputs, args.frames))
    assert out.shape == (args.size, args.size, 4) and np.isfinite(out).all()
    py_ms, cpp_ms = statistics.median(python) * 1e3, statistics.median(cpp) * 1e3
    print(f"hdr_lighting {args.size}x{args.size}, {args.rounds} rounds of {args.frames} frames each way "
          f"(renderer {renderer.size}, rmfx {rmfx.__version__}, Python {sys.version.split()[0]}, "
          f"LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', 'unset')})")
    print(f"  through Python (array in, array out): median {py_ms:8.2f} ms  p10 {np.percentile(python, 10) * 1e3:8.2f}"
          f"  p90 {np.percentile(python, 90) * 1e3:8.2f}")
    print(f"  C++ loop, same executor:              median {cpp_ms:8.2f} ms  p10 {np.percentile(cpp, 10) * 1e3:8.2f}"
          f"  p90 {np.percentile(cpp, 90) * 1e3:8.2f}")
    print(f"  ratio Python / C++: {py_ms / cpp_ms:.3f} (target at most 1.05)")


if __name__ == "__main__":
    main()

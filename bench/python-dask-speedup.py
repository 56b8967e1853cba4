#!/usr/bin/python3
"""A shot split across Dask workers against one process: hdr_lighting over a sequence of arrays,
rendered by Renderer.sequence in this process and by rmfx.dask.render_sequence on a LocalCluster of
N worker processes (one thread each), in one run. Prints the speed-up, and what bounds it: each
task's fixed cost (its own GL context and compiled run), the warm-up frames every chunk after the
first renders again, and the CPU cores llvmpipe already spreads one process's frames over.

    PYTHONPATH=build/python bench/python-dask-speedup.py [--frames 48] [--size 512] [--workers 2]
                                                          [--chunk 24] [--preroll 0]
"""
import argparse
import os
import pathlib
import sys
import time

import numpy as np

import rmfx
import rmfx.dask

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[1]


def shot(count, size):
    rows = np.linspace(0.02, 0.4, size, dtype=np.float32)[:, None]
    cols = np.linspace(0.5, 1.0, size, dtype=np.float32)[None, :]
    frames = []
    for k in range(count):
        image = np.empty((size, size, 4), np.float32)
        image[..., 0] = rows * cols * (1 + 0.05 * k)
        image[..., 1] = rows
        image[..., 2] = cols * 0.1
        image[..., 3] = 1.0
        image[size // 10:size // 5, size // 10:size // 5, :3] = 8.0 + k
        frames.append(image)
    return frames


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=48)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--chunk", type=int, default=24)
    parser.add_argument("--preroll", type=int, default=0)
    args = parser.parse_args()
    import distributed

    frames = shot(args.frames, args.size)
    ws = rmfx.load(SOURCE_DIR / "effects" / "hdr_lighting.xml")

    start = time.perf_counter()
    renderer = ws.renderer()
    first = time.perf_counter()
    one = list(renderer.sequence(frames, preroll=args.preroll))
    single = time.perf_counter() - start
    per_frame = (time.perf_counter() - first) / len(frames)

    with distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                  dashboard_address=None, silence_logs=40) as cluster, distributed.Client(cluster) as client:
        client.run(lambda: __import__("rmfx"))  # the module loaded in every worker before the clock starts
        start = time.perf_counter()
        split = rmfx.dask.render_sequence(client, ws, frames, chunk=args.chunk, preroll=args.preroll)
        spread = time.perf_counter() - start
    assert len(split) == len(one)
    exact = all(np.array_equal(a, b) for a, b in zip(split[:args.chunk], one[:args.chunk]))
    tasks = rmfx.dask.chunks(len(frames), args.chunk, args.preroll)
    warm_up = sum(plan.preroll + plan.skip for _, _, plan in tasks) - args.preroll
    print(f"hdr_lighting {args.size}x{args.size}, {len(frames)} frames, chunks of {args.chunk} "
          f"({len(tasks)} tasks), pre-roll {args.preroll}; {os.cpu_count()} CPUs, "
          f"LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', 'unset')}, Python {sys.version.split()[0]}")
    print(f"  one process (Renderer.sequence):      {single:7.2f} s  ({per_frame * 1e3:.1f} ms a frame after the first)")
    print(f"  {args.workers} Dask worker processes:              {spread:7.2f} s  "
          f"(first chunk bit-identical: {exact})")
    print(f"  speed-up: {single / spread:.2f}x")
    print(f"  bounds: {warm_up} warm-up frames rendered again by later chunks; each task builds its own "
          f"GL context and run; llvmpipe already renders one process's frame on every core")


if __name__ == "__main__":
    main()

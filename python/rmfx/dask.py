"""A shot split across a Dask cluster, one task per chunk, as rmfx render --frame-range runs a chunk.

    import rmfx, rmfx.dask
    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        frames = rmfx.dask.render_sequence(client, "effects/hdr_lighting.xml", paths, chunk=12, preroll=48)

Each chunk renders, before its own frames, the `preroll` frames the whole run renders before them
(rmfx.sequence_chunk), then its frames at the whole run's times: an effect without frame-to-frame
state comes out bit for bit as one Renderer.sequence(frames, preroll=preroll) gives it; one with
state (light adaptation, frame="previous" targets) within the bound its maths gives after `preroll`
frames (docs/sequences.md).
"""
import os

from . import _rmfx


def _render_chunk(workspace, frames, start, preroll, skip, input, inputs, dt, target, size):
    """A worker's task: a renderer of its own (its own GL context) for the chunk's frames."""
    renderer = workspace.renderer(size=size)
    return list(renderer.sequence(frames, input=input, inputs=inputs, dt=dt, preroll=preroll, start=start, skip=skip,
                                  target=target))


def chunks(count, chunk, preroll):
    """The tasks of a shot of `count` frames cut every `chunk` frames: (first, last, SequenceChunk), last included."""
    if count < 1:
        _rmfx._fail("frames: the shot has no frames", "frames")
    if chunk < 1:
        _rmfx._fail(f"chunk: expected frames per task from 1, got {chunk}", "chunk")
    if preroll < 0:
        _rmfx._fail(f"preroll: expected 0 or more frames, got {preroll}", "preroll")
    return [(first, min(first + chunk, count) - 1, _rmfx.sequence_chunk(first, preroll))
            for first in range(0, count, chunk)]


def render_sequence(client, workspace, frames, *, chunk=12, preroll=0, input=None, inputs=None, dt=None, fps=None,
                    target="", size=None):
    """Renders `frames` (paths or arrays, one per frame of the shot) on `client`'s workers, `chunk` frames a task, and
    returns the shot's arrays in order: float32 (height, width, 4), row 0 at the top, as Renderer.sequence yields them.

    workspace: an rmfx.Workspace (pickled to the workers with the values set on it) or a path. preroll: the whole run's
    pre-roll, and each chunk's warm-up (rmfx render --preroll with --frame-range). input, inputs, dt, fps, target and
    size as Renderer.sequence and Workspace.renderer take them. The workspace, the chunking, the time step and the input
    names are checked here, before any task is sent; an rmfx.Error on a worker (an unreadable frame, an unknown target)
    is raised here with its file, line and element, and the other tasks are cancelled."""
    if dt is not None and fps is not None:
        _rmfx._fail("dt and fps both set a sequence's time step (dt = 1 / fps): give one", "fps")
    step = dt if dt is not None else 1.0 / (fps if fps is not None else 24.0)
    if not isinstance(workspace, _rmfx.Workspace):
        workspace = _rmfx.load(os.fspath(workspace))
    workspace.renderer(size=size).sequence([], input=input, inputs=inputs, dt=step)  # checks the names; renders nothing
    frames = list(frames)
    tasks = chunks(len(frames), chunk, preroll)
    # Arrays go to the workers once each, as data of their own, not inside every task that reads
    # them (a chunk's warm-up reads the frames before it too); paths are read by the workers.
    if any(not isinstance(f, (str, os.PathLike)) for f in frames):
        frames = client.scatter(frames, hash=False)  # unique keys: a later call never meets a released one
    futures = []
    for first, last, plan in tasks:
        futures.append(client.submit(_render_chunk, workspace, frames[plan.start:last + 1], plan.start, plan.preroll,
                                     plan.skip, input, inputs, step, target, size, pure=False))
    shot = []
    try:
        for future in futures:
            shot.extend(future.result())
    except BaseException:
        client.cancel(futures)
        raise
    return shot

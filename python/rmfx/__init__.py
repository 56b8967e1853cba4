"""rmfx effect workspaces, rendered headless into NumPy arrays (row 0 at the top). See docs/python.md.

rmfx.load(path) -> Workspace; Workspace.renderer() -> Renderer; Renderer.render(...) -> array;
Renderer.sequence(frames) -> iterator of arrays; rmfx.replay(manifest) -> ReplayReport;
rmfx.dask.render_sequence(client, workspace, frames) splits a shot across Dask workers.
"""
from . import _rmfx
from ._rmfx import *  # noqa: F401,F403  (the compiled module's classes and functions)
from ._rmfx import __version__  # noqa: F401

# The classes say rmfx.Workspace, not rmfx._rmfx.Workspace, in reprs, help and pickles.
for _name in dir(_rmfx):
    _value = getattr(_rmfx, _name)
    if isinstance(_value, type) and getattr(_value, "__module__", "") == _rmfx.__name__:
        try:
            _value.__module__ = __name__
        except (AttributeError, TypeError):
            pass
del _name, _value

#!/usr/bin/env python3
"""Fails when a source file includes from a layer above its own (docs/architecture.md).

The runtime's layers, lowest first, are the folders of runtime/ in RMFX_LAYERS order
(runtime/CMakeLists.txt). A file in runtime/<layer>/ may include "<below>/…" for its own layer and
those below it, never one above; the build enforces the same through each layer's include path,
and this check says it for every file at once, with the line. Also:
  - nothing includes "runtime/…" (layers are included by their own names);
  - GL, EGL and windowing headers appear only in the gl and run layers and the applications;
  - .rfx internals (frontend/rfx/detail/) are included only from frontend/rfx/;
  - unit tests (Test/*Test.cpp not named *GLTest.cpp) include nothing from gl/ or run/: their
    executable links no GL library;
  - the applications: apps/ (what rmfx and rmfx-edit share) includes only the runtime layers up to
    validation and itself; cli/ (rmfx) and editor/ (rmfx-edit) include apps/ and the runtime, never
    each other.
Usage: check-layers.py [--root DIR]   (DIR: the repository, default this script's parent's parent)
"""
import argparse
import pathlib
import re
import sys

LAYERS = ["core", "model", "io", "frontend", "graph", "validation", "compile", "gl", "run"]
GL_LAYERS = {"gl", "run"}
GL_HEADER = re.compile(r"^(epoxy|EGL|GL|GLES\d*|GLFW|X11|wayland)/|^imgui_impl_opengl")
APPS = {"apps", "cli", "editor"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')
SOURCE_ROOTS = ["runtime", "apps", "cli", "editor", "bench", "fuzz", "samples", "tests", "reference", "effects"]


def layer_of_include(path):
    first = path.split("/", 1)[0]
    return first if first in LAYERS and "/" in path else None


def check_file(root, path, problems):
    rel = path.relative_to(root).as_posix()
    parts = rel.split("/")
    own = parts[1] if parts[0] == "runtime" and len(parts) > 2 and parts[1] in LAYERS else None
    is_test = "/Test/" in rel or rel.startswith("tests/")
    is_unit_test = is_test and rel.endswith("Test.cpp") and not rel.endswith("GLTest.cpp")
    try:
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError as e:
        problems.append(f"{rel}: cannot read: {e}")
        return
    for number, line in enumerate(lines, 1):
        m = INCLUDE.match(line)
        if not m:
            continue
        bracket, target = m.group(1), m.group(2)
        where = f"{rel}:{number}"
        if bracket == "<":
            if own is not None and own not in GL_LAYERS and GL_HEADER.search(target):
                problems.append(f"{where}: <{target}> is a GL or windowing header in the '{own}' layer "
                                f"(GL belongs to the gl layer and above)")
            continue
        if target.startswith("runtime/"):
            problems.append(f'{where}: "{target}": include a layer by its name ("{target[len("runtime/"):]}")')
            continue
        used = layer_of_include(target)
        app = parts[0] if parts[0] in APPS else None
        included_app = target.split("/", 1)[0] if "/" in target and target.split("/", 1)[0] in APPS else None
        if app == "apps" and not is_test and (included_app in ("cli", "editor") or
                                             (used is not None and LAYERS.index(used) > LAYERS.index("validation"))):
            problems.append(f'{where}: "{target}": apps/ holds what rmfx and rmfx-edit share, below GL; '
                            f"it includes the runtime up to validation and apps/ only")
        if app in ("cli", "editor") and included_app in ("cli", "editor") and included_app != app:
            problems.append(f'{where}: "{target}": {app}/ and {included_app}/ are separate programs; '
                            f"what both need belongs in apps/")
        if used is None:
            continue
        if own is not None and not is_test and LAYERS.index(used) > LAYERS.index(own):
            problems.append(f'{where}: "{target}" is in the \'{used}\' layer, above this file\'s \'{own}\' '
                            f"layer ({' → '.join(LAYERS)})")
        if target.startswith("frontend/rfx/detail/") and not rel.startswith("runtime/frontend/rfx/") \
                and not rel.startswith("runtime/frontend/Test/") and not rel.startswith("fuzz/"):
            problems.append(f'{where}: "{target}" is an internal of the .rfx importer (frontend/rfx/detail/)')
        if is_unit_test and used in GL_LAYERS:
            problems.append(f'{where}: "{target}" needs GL, but this unit test links no GL library '
                            f"(name it *GLTest.cpp to run it in the GL test executable)")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", type=pathlib.Path, default=pathlib.Path(__file__).resolve().parent.parent)
    args = parser.parse_args()
    root = args.root.resolve()
    problems = []
    files = 0
    for top in SOURCE_ROOTS:
        for path in sorted((root / top).rglob("*")):
            if path.suffix in (".h", ".cpp", ".in") and path.is_file():
                files += 1
                check_file(root, path, problems)
    for p in problems:
        print(p)
    if problems:
        sys.stdout.flush()
        print(f"check-layers: {len(problems)} include(s) break the layering, in {files} files", file=sys.stderr)
        return 1
    print(f"check-layers: {files} files, every include within the layering ({' → '.join(LAYERS)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Fails when a source file includes from a layer its own does not use (docs/architecture.md).

The runtime's layers are the folders of runtime/; runtime/layers.txt lists them and the layers each
one uses directly (a DAG), and runtime/CMakeLists.txt builds from the same file. A file in
runtime/<layer>/ may include "<used>/…" for its own layer and the layers it uses, directly or
through others (its closure), nothing else; the build enforces the same through each layer's
include path, and this check says it for every file at once, with the line. A layer declares exactly
the layers its files include directly: one declared and never included, or one included only
through another's declaration, fails too. Tests of a layer (runtime/<layer>/Test/) may include
besides what layers.txt says they use ("<layer> tests: …"). Also:
  - nothing includes "runtime/…" (layers are included by their own names);
  - GL, EGL and windowing headers appear only in the gl and run layers and the applications;
  - .rfx internals (frontend/rfx/detail/) are included only from frontend/rfx/;
  - unit tests (Test/*Test.cpp not named *GLTest.cpp) include nothing from gl/ or run/: their
    executables link no GL library;
  - the applications: apps/ (what rmfx and rmfx-edit share) includes only the validation layer, its
    closure and itself; cli/ (rmfx), editor/ (rmfx-edit) and python/ (import rmfx) include apps/ and
    the runtime, never each other.
Usage: check-layers.py [--root DIR]   (DIR: the repository, default this script's parent's parent)
"""
import argparse
import pathlib
import re
import sys

LAYERS_FILE = "runtime/layers.txt"
GL_LAYERS = {"gl", "run"}
GL_HEADER = re.compile(r"^(epoxy|EGL|GL|GLES\d*|GLFW|X11|wayland)/|^imgui_impl_opengl")
APPS = {"apps", "cli", "editor", "python"}
PROGRAMS = ("cli", "editor", "python")  # the applications at the edge, apart from each other
APPS_UP_TO = "validation"  # apps/ includes this layer, what it uses, and itself
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')
DECLARATION = re.compile(r"^([a-z]+)( tests)?:([a-z ]*)$")
SOURCE_ROOTS = ["runtime", "apps", "cli", "editor", "python", "bench", "fuzz", "samples", "tests", "reference", "effects"]


class Layers:
    """runtime/layers.txt: the layers in order, what each uses directly, and the closure of that."""

    def __init__(self, root, problems):
        self.order = []
        self.uses = {}        # layer → the layers it declares
        self.closure = {}     # layer → the layers it uses, directly or through others
        self.test_uses = {}   # layer → what its tests use besides
        self.line = {}        # (layer, tests?) → its line in the file
        path = root / LAYERS_FILE
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as e:
            problems.append(f"{LAYERS_FILE}: cannot read: {e}")
            return
        for number, line in enumerate(text.splitlines(), 1):
            if not line.strip() or line.startswith("#"):
                continue
            m = DECLARATION.match(line)
            if not m:
                problems.append(f"{LAYERS_FILE}:{number}: cannot read '{line}' (LAYER: USED… or LAYER tests: USED…)")
                continue
            layer, tests, used = m.group(1), bool(m.group(2)), m.group(3).split()
            self.line[(layer, tests)] = number
            if tests:
                self.test_uses[layer] = used
                continue
            closure = set()
            for u in used:
                if u not in self.uses:
                    problems.append(f"{LAYERS_FILE}:{number}: '{layer}' uses '{u}', which is not listed above it")
                    continue
                closure |= {u} | self.closure[u]
            self.order.append(layer)
            self.uses[layer] = used
            self.closure[layer] = closure
        for layer in self.test_uses:
            if layer not in self.uses:
                problems.append(f"{LAYERS_FILE}:{self.line[(layer, True)]}: tests of '{layer}', which is no layer")

    def allowed(self, layer, tests):
        """What a file of `layer` (of its tests when `tests`) may include."""
        allowed = {layer} | self.closure.get(layer, set())
        if tests:
            for u in self.test_uses.get(layer, []):
                allowed |= {u} | self.closure.get(u, set())
        return allowed

    def describe(self, layer):
        used = sorted(self.closure.get(layer, set()), key=self.order.index)
        return ", ".join(used) if used else "no other layer"


def layer_of_include(layers, path):
    first = path.split("/", 1)[0]
    return first if first in layers.uses and "/" in path else None


def check_file(root, path, layers, problems, included):
    rel = path.relative_to(root).as_posix()
    parts = rel.split("/")
    own = parts[1] if parts[0] == "runtime" and len(parts) > 2 and parts[1] in layers.uses else None
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
                                f"(GL belongs to the gl layer and the layers that use it)")
            continue
        if target.startswith("runtime/"):
            problems.append(f'{where}: "{target}": include a layer by its name ("{target[len("runtime/"):]}")')
            continue
        used = layer_of_include(layers, target)
        app = parts[0] if parts[0] in APPS else None
        included_app = target.split("/", 1)[0] if "/" in target and target.split("/", 1)[0] in APPS else None
        if app == "apps" and not is_test and (included_app in PROGRAMS or
                                             (used is not None and used not in layers.allowed(APPS_UP_TO, False))):
            problems.append(f'{where}: "{target}": apps/ holds what rmfx and rmfx-edit share, below GL; '
                            f"it includes the runtime up to {APPS_UP_TO} (and what that uses) and apps/ only")
        if app in PROGRAMS and included_app in PROGRAMS and included_app != app:
            problems.append(f'{where}: "{target}": {app}/ and {included_app}/ are separate programs; '
                            f"what both need belongs in apps/")
        if used is None:
            continue
        if own is not None:
            if not is_test and used != own:
                included.setdefault(own, {}).setdefault(used, where)
            if is_test and not rel.endswith("GLTest.cpp") and used != own and used not in layers.allowed(own, False):
                included.setdefault((own, "tests"), {}).setdefault(used, where)
            # GL tests build into the one GL test executable, which links every layer.
            checked = not is_test or not rel.endswith("GLTest.cpp")
            if checked and used not in layers.allowed(own, is_test):
                relation = "above" if own in layers.closure.get(used, set()) else "beside"
                if is_test:
                    extra = layers.test_uses.get(own, [])
                    uses = layers.describe(own) + (f", and {', '.join(extra)} for its tests" if extra else "")
                    problems.append(f'{where}: "{target}" is in the \'{used}\' layer, {relation} this test\'s '
                                    f"'{own}' layer, whose tests use only {uses} ({LAYERS_FILE})")
                else:
                    problems.append(f'{where}: "{target}" is in the \'{used}\' layer, {relation} this file\'s '
                                    f"'{own}' layer, which uses only {layers.describe(own)} ({LAYERS_FILE})")
        if target.startswith("frontend/rfx/detail/") and not rel.startswith("runtime/frontend/rfx/") \
                and not rel.startswith("runtime/frontend/Test/") and not rel.startswith("fuzz/"):
            problems.append(f'{where}: "{target}" is an internal of the .rfx importer (frontend/rfx/detail/)')
        if is_unit_test and used in GL_LAYERS:
            problems.append(f'{where}: "{target}" needs GL, but this unit test links no GL library '
                            f"(name it *GLTest.cpp to run it in the GL test executable)")


def check_declarations(layers, included, problems):
    """Each layer declares exactly the layers its files include, its tests exactly what they add."""
    for layer in layers.order:
        where = f"{LAYERS_FILE}:{layers.line[(layer, False)]}"
        direct = included.get(layer, {})
        for used in layers.uses[layer]:
            if used not in direct:
                problems.append(f"{where}: '{layer}' declares '{used}', but no file of runtime/{layer}/ includes it")
        for used, first in direct.items():
            if used not in layers.uses[layer] and used in layers.closure[layer]:
                problems.append(f"{where}: '{layer}' includes '{used}' ({first}) without declaring it "
                                f"(it reaches it only through another layer)")
        if layer in layers.test_uses:
            where = f"{LAYERS_FILE}:{layers.line[(layer, True)]}"
            beyond = included.get((layer, "tests"), {})
            for used in layers.test_uses[layer]:
                if used not in beyond:
                    problems.append(f"{where}: '{layer}' tests declare '{used}', but no test of runtime/{layer}/ "
                                    f"includes it beyond the layer's own")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", type=pathlib.Path, default=pathlib.Path(__file__).resolve().parent.parent)
    args = parser.parse_args()
    root = args.root.resolve()
    problems = []
    layers = Layers(root, problems)
    included = {}
    files = 0
    for top in SOURCE_ROOTS:
        for path in sorted((root / top).rglob("*")):
            if path.suffix in (".h", ".cpp", ".in") and path.is_file():
                files += 1
                check_file(root, path, layers, problems, included)
    check_declarations(layers, included, problems)
    for p in problems:
        print(p)
    if problems:
        sys.stdout.flush()
        print(f"check-layers: {len(problems)} problem(s) with the layering, in {files} files", file=sys.stderr)
        return 1
    print(f"check-layers: {files} files, every include within the layers' DAG ({LAYERS_FILE}: "
          + "; ".join(f"{l} uses {', '.join(layers.uses[l]) or 'nothing'}" for l in layers.order) + ")")
    return 0


if __name__ == "__main__":
    sys.exit(main())

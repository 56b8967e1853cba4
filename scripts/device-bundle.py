#!/usr/bin/env python3
"""Packs rmfx programs with the shared libraries they load, for a machine without Debian's packages
(a lent GPU machine: docs/performance.md, "On a GPU").

    scripts/device-bundle.py OUT_DIR build/rmfx build/rmfx_bench_effects ...

OUT_DIR/bin gets the stripped programs, OUT_DIR/lib the libraries; run them with
LD_LIBRARY_PATH=OUT_DIR/lib. The C and C++ runtimes and the GL/EGL loaders are left to the target
(newer there, and the GPU's driver comes with its own). OpenImageIO links codecs and toolkits rmfx
never calls (OpenVDB, GDAL, FFmpeg, OpenCV, ICU data: 360 MB in all), too large to carry: each of
those is replaced by a stub library that defines, with the same versions, the symbols the carried
libraries import from it: functions that return a pointer to zeroed memory (an empty string: at
start OpenImageIO asks each codec library for its version, and its constructors call into DCMTK,
so a trap would not do), and zeroed objects. The bundle's check is that a render with the
stubs gives the same bytes as the real build here.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

# Left to the target: the C/C++ runtimes and the GL loaders (libglvnd, matched to its driver).
SYSTEM = re.compile(r"^(libc|libm|libdl|libpthread|librt|ld-linux-x86-64|libstdc\+\+|libgcc_s|libGL|libEGL|libGLX|"
                    r"libGLdispatch|libOpenGL|libGLESv2)\.so")
# What rmfx's own code reaches: carried as they are, however large.
NEEDED_REAL = re.compile(r"^lib(OpenImageIO|OpenImageIO_Util|OpenEXR|OpenEXRCore|OpenEXRUtil|Iex|IlmThread|Imath|"
                         r"png16|jpeg|z|deflate|tiff|assimp|draco|minizip|spirv-cross|glslang|SPIRV|tinyxml2|stb|glfw|"
                         r"epoxy|benchmark|tbb|OpenColorIO|yaml-cpp|pystring|expat|lcms2|boost_|fmt|zstd|lzma|bz2)[-_.a-z0-9]*\.so")
STUB_OVER_BYTES = 256 * 1024


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def needed(path):
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", run("readelf", "-d", "-W", path))


def resolved(programs):
    """soname -> path, as the dynamic linker here finds them."""
    names = {}
    for p in programs:
        for m in re.finditer(r"^\s*(\S+) => (\S+)", run("ldd", p), re.M):
            names[m.group(1)] = os.path.realpath(m.group(2))
    return names


def dynsyms(path):
    """(name, version, default?, type, size, defined?) of each dynamic symbol."""
    out = []
    for line in run("readelf", "--dyn-syms", "-W", path).splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].endswith(":") or not f[0][:-1].isdigit():
            continue
        size = int(f[2], 16) if f[2].startswith("0x") else int(f[2])
        name, version, default = f[7], "", True
        if "@@" in name:
            name, version = name.split("@@", 1)
        elif "@" in name:
            name, version = name.split("@", 1)
            default = False
        version = re.sub(r" \(\d+\)$", "", version)
        out.append((name, version, default, f[3], size, f[6] != "UND"))
    return out


def soname(path):
    m = re.search(r"\(SONAME\)\s+Library soname: \[([^\]]+)\]", run("readelf", "-d", "-W", path))
    return m.group(1) if m else os.path.basename(path)


def build_stub(original, imported, out_path, work):
    """A library named as ORIGINAL, defining the symbols in IMPORTED that ORIGINAL defines."""
    lines, versions, n = [], set(), 0
    for name, version, default, kind, size, defined in dynsyms(original):
        if not defined or kind in ("FILE", "SECTION") or name not in imported or (name, version) in versions:
            continue
        versions.add((name, version))
        label = f"stub_{n}"
        n += 1
        if kind == "OBJECT":
            lines += ["\t.bss", "\t.balign 16", f'\t.type {label},@object', f'\t.size {label},{max(size, 1)}',
                      f"{label}:", f"\t.zero {max(size, 1)}"]
        elif kind == "TLS":
            lines += ['\t.section .tbss,"awT",@nobits', "\t.balign 16", f'\t.type {label},@object',
                      f'\t.size {label},{max(size, 1)}', f"{label}:", f"\t.zero {max(size, 1)}"]
        else:
            lines += ["\t.text", f'\t.type {label},@function', f"{label}:", "\tleaq stub_zeroes(%rip),%rax", "\tret"]
        lines.append(f'\t.globl {label}')
        if version:
            lines.append(f'\t.symver {label},"{name}{"@@" if default else "@"}{version}"')
        else:
            lines.append(f'\t.set "{name}",{label}')
            lines.append(f'\t.globl "{name}"')
            if kind in ("OBJECT", "TLS"):
                lines.append(f'\t.type "{name}",@object')
                lines.append(f'\t.size "{name}",{max(size, 1)}')
    lines += ["\t.bss", "\t.balign 64", "stub_zeroes:", "\t.zero 256"]
    asm = os.path.join(work, "stub.s")
    with open(asm, "w") as f:
        f.write("\n".join(lines) + "\n")
    nodes = sorted({v for (_, v) in versions if v})
    script = os.path.join(work, "stub.map")
    with open(script, "w") as f:
        for i, v in enumerate(nodes):
            f.write(f"{v} {{ {'local: stub_*;' if i == 0 else ''} }};\n")
        if not nodes:
            f.write("{ local: stub_*; };\n")
    subprocess.run(["cc", "-shared", "-nostdlib", "-o", out_path, asm, f"-Wl,-soname,{soname(original)}",
                    f"-Wl,--version-script={script}"], check=True)
    return n


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, programs = sys.argv[1], sys.argv[2:]
    # rmfx starts glslang's HLSL front end as a program found beside itself (frontend/shader/HlslWorker.h)
    # and loads OpenImageIO through a module beside itself (io/image/ImageCodecs.h).
    for p in list(programs):
        for companion in ("rmfx-hlsl-worker", "rmfx-image-codecs.so"):
            path = os.path.join(os.path.dirname(p), companion)
            if os.path.exists(path) and path not in programs:
                programs.append(path)
    names = resolved(programs)
    real, stub, queue = set(), set(), []
    for p in programs:
        queue += needed(p)
    while queue:
        lib = queue.pop()
        if lib in real or lib in stub or SYSTEM.match(lib):
            continue
        if lib not in names:
            sys.exit(f"device-bundle: {lib} is not found here (ldd)")
        if os.path.getsize(names[lib]) > STUB_OVER_BYTES and not NEEDED_REAL.match(lib):
            stub.add(lib)
        else:
            real.add(lib)
            queue += needed(names[lib])
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(f"{out}/bin")
    os.makedirs(f"{out}/lib")
    for p in programs:
        subprocess.run(["strip", "-o", f"{out}/bin/{os.path.basename(p)}", p], check=True)
    imported = set()
    for lib in real:
        shutil.copy(names[lib], f"{out}/lib/{lib}")
        subprocess.run(["strip", "--strip-unneeded", f"{out}/lib/{lib}"], check=True)
        imported |= {s[0] for s in dynsyms(names[lib]) if not s[5]}
    for p in programs:
        imported |= {s[0] for s in dynsyms(p) if not s[5]}
    with tempfile.TemporaryDirectory() as work:
        for lib in sorted(stub):
            count = build_stub(names[lib], imported, f"{out}/lib/{lib}", work)
            print(f"stub {lib}: {count} symbols (was {os.path.getsize(names[lib]) // 1024} KiB)")
    print(f"{len(real)} libraries carried, {len(stub)} stubbed")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Packs built hipr binaries with the shared libraries they load into one archive, for a GPU
machine that has a Vulkan driver but none of hipr's Debian packages (BENCHMARKS.md, "On a GPU").

    python3 tools/gpu_bundle.py ARCHIVE.tar.xz [BINARY...]      (default: build/hipr)

On the machine: `tar -xJf ARCHIVE.tar.xz -C DIR`, then run DIR/bin/hipr (or DIR/bin/render_test).

- The C library and the C++ runtime stay the machine's own: a newer glibc and libstdc++ run
  binaries built against older ones.
- Everything else travels, the Vulkan loader included, except the back-ends of image formats hipr
  never opens. Debian's OpenImageIO links video (FFmpeg), DICOM, OpenVDB, HEIF and OpenCV, whose
  own dependencies (GDAL, codecs, ICU...) make up nine tenths of the 260 libraries and would not
  fit a machine's transfer. Each of those travels as a stand-in of the same name that exports
  every symbol the real one defines for itself, with its versions, so the loader binds
  OpenImageIO (built with BIND_NOW) as usual; a function of a stand-in returns a pointer to zeros.
  hipr's images are EXR, PNG and HDR, and stb decodes glTF textures.
- The Khronos validation layer travels too (the tests run under it).
- Each binary is stripped of its debug information and started through a wrapper that points
  only that process at the carried libraries and layer: the machine's own tools (python3) are
  untouched.
"""
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

# The machine's own libraries.
OWN = re.compile(r"^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|"
                 r"libstdc\+\+\.so|libgcc_s\.so)")
# The validation layer (its manifest names the library without a folder: found through the
# wrapper's library path).
VALIDATION_LAYER = Path("/usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so")
VALIDATION_MANIFEST = Path("/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json")
# OpenImageIO back-ends hipr does not use: replaced by stand-ins (see the docstring).
STAND_INS = {
    "libopencv_core.so.406", "libopencv_imgproc.so.406", "libopencv_videoio.so.406",
    "libdcmimage.so.17", "libdcmimgle.so.17", "libdcmdata.so.17", "liboflog.so.17", "libofstd.so.17",
    "libavcodec.so.59", "libavformat.so.59", "libavutil.so.57", "libswscale.so.6",
    "libheif.so.1", "libopenvdb.so.10.0",
}


def run(*command: str, env: dict[str, str] | None = None) -> str:
    return subprocess.run(command, check=True, capture_output=True, text=True, env=env).stdout


def resolved_paths(binary: Path, env: dict[str, str] | None = None) -> dict[str, str]:
    """soname -> path, as the loader on this machine finds them (in that environment)."""
    paths = {}
    for line in run("ldd", str(binary), env=env).splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[1] == "=>" and parts[2].startswith("/"):
            paths[parts[0]] = parts[2]
    return paths


def needed(path: str) -> list[str]:
    return re.findall(r"\(NEEDED\).*\[(.*)\]", run("readelf", "-d", path))


def closure(binary: Path, paths: dict[str, str]) -> tuple[list[str], list[str]]:
    """The libraries to carry and the stand-ins to make, walking NEEDED from the binary."""
    carried, stand_ins, seen, todo = [], [], set(), [str(binary)]
    while todo:
        for name in needed(todo.pop()):
            if name in seen or OWN.match(name):
                continue
            seen.add(name)
            if name in STAND_INS:
                stand_ins.append(name)
            else:
                carried.append(name)
                todo.append(paths[name])
    return carried, stand_ins


def make_stand_in(real: str, soname: str, out: Path, work: Path) -> None:
    """A library named soname exporting real's symbols (default versions), none of its code."""
    listing = run("nm", "-D", "-S", "--defined-only", "--with-symbol-versions", real)
    asm = [".text", ".p2align 4", "stand_in_zero_return:", "  leaq stand_in_zeros(%rip), %rax", "  ret",
           ".bss", ".p2align 12", "stand_in_zeros:", "  .zero 4096"]
    versions: dict[str, list[str]] = {}
    defined = set()
    for line in listing.splitlines():
        fields = line.split()
        if len(fields) == 4:
            _, size, kind, symbol = fields
        elif len(fields) == 3:
            _, kind, symbol = fields
            size = "0"
        else:
            continue
        if kind == "A" or "@@" not in symbol and "@" in symbol:
            continue  # version nodes themselves; non-default (older) versions nobody links against
        if kind in "WVwvu":
            # Vague linkage (templates, inline functions, vtables of std:: types): every library
            # using one has its own copy, and a stand-in exporting zeros in its place would capture
            # the references of libraries loaded later (lavapipe's LLVM crashed on such a vtable).
            continue
        name, _, version = symbol.partition("@@")
        if name in defined:
            continue
        defined.add(name)
        if version:
            versions.setdefault(version, []).append(name)
        if kind in "Tti":
            asm += [".text", f".globl {name}", f".type {name}, @function", f".set {name}, stand_in_zero_return"]
        else:  # data: as many zeros as the real object has
            asm += [".data", ".p2align 4", f".globl {name}", f".type {name}, @object",
                    f".size {name}, {max(int(size, 16), 1)}", f"{name}:", f"  .zero {max(int(size, 16), 1)}"]
    source = work / f"{soname}.s"
    source.write_text("\n".join(asm) + "\n.section .note.GNU-stack,\"\",@progbits\n")
    command = ["gcc", "-shared", "-o", str(out), str(source), f"-Wl,-soname,{soname}"]
    if versions:
        script = work / f"{soname}.map"
        script.write_text("".join(f"{v} {{ global: {'; '.join(names)}; }};\n" for v, names in versions.items()))
        command.append(f"-Wl,--version-script={script}")
    subprocess.run(command, check=True)


WRAPPER = """#!/bin/sh
here=$(dirname "$(readlink -f "$0")")
export VK_LAYER_PATH="${{VK_LAYER_PATH:-$here/../layers}}"
LD_LIBRARY_PATH="$here/../lib${{LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}}" exec "$here/{name}.real" "$@"
"""


def bundle(archive: Path, binaries: list[Path]) -> int:
    """Writes the archive (bin/, lib/, layers/); returns how many libraries it holds."""
    with tempfile.TemporaryDirectory() as temp:
        stage = Path(temp) / "stage"
        for folder in ("bin", "lib", "layers"):
            (stage / folder).mkdir(parents=True)
        if VALIDATION_LAYER.exists() and VALIDATION_MANIFEST.exists():
            shutil.copy(VALIDATION_LAYER, stage / "lib")
            shutil.copy(VALIDATION_MANIFEST, stage / "layers")
        made = set()
        for binary in binaries:
            paths = resolved_paths(binary)
            carried, stand_ins = closure(binary, paths)
            for name in carried:
                if name not in made:
                    shutil.copy(paths[name], stage / "lib" / name)  # follows the link to the file
                    made.add(name)
            for name in stand_ins:
                if name not in made:
                    make_stand_in(os.path.realpath(paths[name]), name, stage / "lib" / name, Path(temp))
                    made.add(name)
            subprocess.run(["objcopy", "--strip-debug", str(binary), str(stage / "bin" / f"{binary.name}.real")],
                           check=True)
            wrapper = stage / "bin" / binary.name
            wrapper.write_text(WRAPPER.format(name=binary.name))
            wrapper.chmod(0o755)
        with tarfile.open(archive, "w:xz") as tar:
            for folder in ("bin", "lib", "layers"):
                tar.add(stage / folder, folder)
        return len(made)


def main() -> None:
    if len(sys.argv) < 2:
        sys.exit("usage: gpu_bundle.py ARCHIVE.tar.xz [BINARY...]")
    archive = Path(sys.argv[1])
    root = Path(__file__).resolve().parent.parent
    binaries = [Path(b) for b in sys.argv[2:]] or [root / "build" / "hipr"]
    libraries = bundle(archive, binaries)
    print(f"{archive}: {archive.stat().st_size / 2**20:.1f} MiB ({libraries} libraries, {len(binaries)} binaries)")


if __name__ == "__main__":
    main()

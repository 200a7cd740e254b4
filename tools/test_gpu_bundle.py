#!/usr/bin/env python3
"""Tests for tools/gpu_bundle.py: its stand-in libraries, and a bundle of hipr that runs from
its own libraries and renders what the build renders, bit for bit.

Run: python3 tools/test_gpu_bundle.py HIPR   (exits non-zero on failure; HIPR: build/hipr)
"""

import ctypes
import os
import subprocess
import sys
import tarfile
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import gpu_bundle  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
HIPR = Path(sys.argv.pop(1)) if len(sys.argv) > 1 else ROOT / "build" / "hipr"


def exported(library: Path, kinds: str) -> set[str]:
    """name@@version (or name) of the symbols of these nm kinds the library defines."""
    listing = subprocess.run(["nm", "-D", "--defined-only", "--with-symbol-versions", str(library)],
                             check=True, capture_output=True, text=True).stdout
    return {fields[2] for fields in map(str.split, listing.splitlines())
            if len(fields) == 3 and fields[1] in kinds and ("@" not in fields[2] or "@@" in fields[2])}


class StandIn(unittest.TestCase):
    def setUp(self):
        self.temp = tempfile.TemporaryDirectory()
        self.dir = Path(self.temp.name)
        self.paths = gpu_bundle.resolved_paths(HIPR)

    def tearDown(self):
        self.temp.cleanup()

    def stand_in_for(self, soname: str) -> tuple[Path, Path]:
        real = Path(os.path.realpath(self.paths[soname]))
        out = self.dir / soname
        gpu_bundle.make_stand_in(str(real), soname, out, self.dir)
        return real, out

    def test_exports_the_real_functions_with_their_versions_and_name(self):
        real, stand_in = self.stand_in_for("libz.so.1")
        functions = exported(real, "T")
        self.assertTrue(any("@@ZLIB_" in f for f in functions), "libz versions its symbols")
        self.assertEqual(exported(stand_in, "T"), functions)
        dynamic = subprocess.run(["readelf", "-d", str(stand_in)], check=True, capture_output=True, text=True).stdout
        self.assertIn("Library soname: [libz.so.1]", dynamic)
        self.assertNotIn("libz.so.1", gpu_bundle.needed(str(stand_in)))

    def test_a_function_returns_a_pointer_to_zeros(self):
        _, stand_in = self.stand_in_for("libz.so.1")
        library = ctypes.CDLL(str(stand_in))
        library.zlibVersion.restype = ctypes.c_char_p
        self.assertEqual(library.zlibVersion(), b"")

    def test_leaves_out_vague_linkage(self):
        # A C++ library's template and inline definitions: a stand-in exporting zeros for them would
        # capture the references of every library loaded after it.
        real, stand_in = self.stand_in_for("libOpenImageIO_Util.so.2.4")
        vague = {name.split("@")[0] for name in exported(real, "WVu")}
        self.assertTrue(vague, "the real library has vague-linkage symbols to leave out")
        every = {name.split("@")[0] for name in exported(stand_in, "TtWwVvuBbDdRr")}
        self.assertFalse(vague & every)


class Bundle(unittest.TestCase):
    def test_hipr_runs_from_its_bundle_and_renders_the_same_pixels(self):
        with tempfile.TemporaryDirectory() as temp:
            temp = Path(temp)
            self.assertGreater(gpu_bundle.bundle(temp / "hipr.tar.xz", [HIPR]), 10)
            with tarfile.open(temp / "hipr.tar.xz") as tar:
                tar.extractall(temp / "b")
            bundled = temp / "b" / "bin" / "hipr"
            # Every library it loads but the machine's own C and C++ runtime comes from the bundle.
            environment = dict(os.environ, LD_LIBRARY_PATH=str(temp / "b" / "lib"))
            loaded = gpu_bundle.resolved_paths(temp / "b" / "bin" / "hipr.real", environment)
            for soname, path in loaded.items():
                if not gpu_bundle.OWN.match(soname):
                    self.assertTrue(path.startswith(str(temp / "b" / "lib")), f"{soname} => {path}")
            scene = ROOT / "assets" / "scenes" / "cornell_sphere.glb"
            options = ["--width", "24", "--height", "16", "--spp", "2", "-q"]
            subprocess.run([str(bundled), "render", str(scene), "-o", str(temp / "bundled.exr"), "-o",
                            str(temp / "bundled.png")] + options, check=True)
            subprocess.run([str(HIPR), "render", str(scene), "-o", str(temp / "built.exr")] + options, check=True)
            compared = subprocess.run([str(bundled), "compare", str(temp / "bundled.exr"), str(temp / "built.exr"),
                                       "--metric", "max", "--threshold", "0"], capture_output=True, text=True)
            self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)
            self.assertGreater((temp / "bundled.png").stat().st_size, 0)


if __name__ == "__main__":
    unittest.main()

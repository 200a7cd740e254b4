#!/usr/bin/env python3
"""Writes small GLB scenes whose one texture is a WebP, AVIF or DDS image held in the binary
chunk, as seeds for the glTF fuzz target (tools/fuzz.sh): the images go to their own decoders
(libwebp, libheif, hipr's DDS decoder), which a fuzzer starting from text or PNG-textured scenes
would rarely reach. The image bytes lie raw in the GLB, so the fuzzer mutates their headers
directly.

usage: fuzz_texture_seeds.py OUTDIR   (needs oiiotool for the WebP and AVIF images)
"""
import json
import os
import struct
import subprocess
import sys
import tempfile


def dds_uncompressed(w, h):
    """A 32-bit BGRA DDS (the DDS_HEADER written field by field)."""
    header = [0] * 31
    header[0] = 124                          # dwSize
    header[1] = 0x1 | 0x2 | 0x4 | 0x1000     # CAPS, HEIGHT, WIDTH, PIXELFORMAT
    header[2], header[3] = h, w
    header[4] = w * 4                        # pitch
    header[18] = 32                          # DDS_PIXELFORMAT.dwSize
    header[19] = 0x40 | 0x1                  # RGB, ALPHAPIXELS
    header[21] = 32                          # bits per texel
    header[22:26] = [0x00FF0000, 0x0000FF00, 0x000000FF, 0xFF000000]
    header[26] = 0x1000                      # DDSCAPS_TEXTURE
    texels = bytes(b for y in range(h) for x in range(w) for b in (200, y * 60 % 256, x * 60 % 256, 255))
    return b"DDS " + struct.pack("<31I", *header) + texels


def dds_blocks(w, h, mips, four_cc=b"DXT1"):
    """A block-compressed DDS (DXT1: BC1, DXT5: BC3, ATI2: BC5) with `mips` levels."""
    block = struct.pack("<HHI", 0xF800, 0x001F, 0x1B1B1B1B)  # BC1 colours, or a BC4 value block
    if four_cc != b"DXT1":
        block = struct.pack("<BB6B", 240, 16, 0x88, 0xC6, 0xFA, 0x05, 0x39, 0xA7) + block
    header = [0] * 31
    header[0] = 124
    header[1] = 0x1 | 0x2 | 0x4 | 0x1000 | 0x80000 | (0x20000 if mips > 1 else 0)  # LINEARSIZE, MIPMAPCOUNT
    header[2], header[3] = h, w
    header[4] = max(1, (w + 3) // 4) * max(1, (h + 3) // 4) * len(block)
    header[6] = mips
    header[18] = 32
    header[19] = 0x4                         # FOURCC
    header[20] = struct.unpack("<I", four_cc)[0]
    header[26] = 0x1000 | (0x400008 if mips > 1 else 0)
    blocks = b""
    lw, lh = w, h
    for _ in range(mips):
        n = max(1, (lw + 3) // 4) * max(1, (lh + 3) // 4)
        blocks += block * n
        lw, lh = max(1, lw // 2), max(1, lh // 2)
    return b"DDS " + struct.pack("<31I", *header) + blocks


def oiio_image(extension):
    """An 8x8 checker written by oiiotool in the format the extension names."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "checker." + extension)
        subprocess.run(["oiiotool", "--pattern", "checker:width=2:height=2:color1=1,0.5,0.2:color2=0,0.1,0.3",
                        "8x8", "3", "-d", "uint8", "-o", path], check=True)
        with open(path, "rb") as f:
            return f.read()


def glb(image, mime, extension):
    """A textured quad whose texture's only source is `image`, through `extension`."""
    positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)
    uvs = struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    chunks = [positions, uvs, indices, image]
    views, binary = [], b""
    for chunk in chunks:
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(chunk)})
        binary += chunk + b"\0" * (-len(chunk) % 4)
    doc = {
        "asset": {"version": "2.0"},
        "extensionsUsed": [extension],
        "extensionsRequired": [extension],
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}, "emissiveFactor": [1, 1, 1],
                       "emissiveTexture": {"index": 0}}],
        "textures": [{"extensions": {extension: {"source": 0}}}],
        "images": [{"bufferView": 3, "mimeType": mime}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(binary)}],
    }
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    seeds = {
        "texture_dds_bgra.glb": (dds_uncompressed(4, 3), "image/vnd-ms.dds", "MSFT_texture_dds"),
        "texture_dds_dxt1.glb": (dds_blocks(8, 8, 4), "image/vnd-ms.dds", "MSFT_texture_dds"),
        "texture_dds_dxt5.glb": (dds_blocks(6, 5, 1, b"DXT5"), "image/vnd-ms.dds", "MSFT_texture_dds"),
        "texture_dds_ati2.glb": (dds_blocks(8, 4, 2, b"ATI2"), "image/vnd-ms.dds", "MSFT_texture_dds"),
        "texture_webp.glb": (oiio_image("webp"), "image/webp", "EXT_texture_webp"),
        "texture_avif.glb": (oiio_image("avif"), "image/avif", "EXT_texture_avif"),
    }
    for name, (image, mime, extension) in seeds.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(glb(image, mime, extension))


if __name__ == "__main__":
    main()

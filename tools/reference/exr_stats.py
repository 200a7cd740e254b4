#!/usr/bin/python3
"""Print size, channels, mean/min/max RGB and the brightest pixels of an EXR.

Usage: /usr/bin/python3 tools/reference/exr_stats.py IMAGE.exr [--png OUT.png [--scale N]]
Needs Debian's python3-openimageio and python3-numpy (use /usr/bin/python3).
--png writes an sRGB-encoded preview (clipped to [0,1]), nearest-neighbour upscaled N times.
"""
import argparse

import numpy as np
import OpenImageIO as oiio


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("image")
    ap.add_argument("--png")
    ap.add_argument("--scale", type=int, default=4)
    a = ap.parse_args()
    inp = oiio.ImageInput.open(a.image)
    if inp is None:
        raise SystemExit(oiio.geterror())
    spec = inp.spec()
    px = np.asarray(inp.read_image(oiio.FLOAT), dtype=np.float64)
    inp.close()
    names = list(spec.channelnames)
    print("%s: %dx%d channels=%s format=%s" % (a.image, spec.width, spec.height, names, spec.format))
    rgb = px[..., :3]
    flat = rgb.reshape(-1, 3)
    print("mean RGB = %.6f %.6f %.6f" % tuple(flat.mean(axis=0)))
    print("min  RGB = %.6f %.6f %.6f" % tuple(flat.min(axis=0)))
    print("max  RGB = %.6f %.6f %.6f" % tuple(flat.max(axis=0)))
    print("non-finite values: %d" % int(np.sum(~np.isfinite(px))))
    lum = flat @ np.array([0.2126, 0.7152, 0.0722])
    order = np.argsort(lum)[::-1][:5]
    for i in order:
        y, x = divmod(int(i), spec.width)
        print("  bright pixel (x=%d, y=%d from top): %.4f %.4f %.4f" % ((x, y) + tuple(flat[i])))
    if a.png:
        c = np.clip(rgb, 0.0, 1.0)
        srgb = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)
        img = np.repeat(np.repeat(srgb, a.scale, axis=0), a.scale, axis=1)
        out = oiio.ImageBuf(oiio.ImageSpec(img.shape[1], img.shape[0], 3, oiio.UINT8))
        out.set_pixels(oiio.ROI(0, img.shape[1], 0, img.shape[0], 0, 1, 0, 3),
                       np.ascontiguousarray(img, dtype=np.float32))
        if not out.write(a.png):
            raise SystemExit(out.geterror())
        print("wrote %s" % a.png)


main()

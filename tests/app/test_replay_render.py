#!/usr/bin/env python3
"""The 3-D replay page rendered by headless Chromium: `cairn run --replay` of a cube falling onto a
fixed cube, screenshots at two times (?t=), the canvas must draw both blocks and the free one must
have moved down; then `cairn replay` of two runs side by side draws both views.

usage: replay_render_test.py CAIRN SCRATCH_DIR; exit 77 (skipped) when chromium is missing.
The screenshots stay in SCRATCH_DIR/replay/*.png for a look."""
import os
import shutil
import struct
import subprocess
import sys
import zlib

CAIRN, SCRATCH = sys.argv[1], os.path.join(sys.argv[2], "replay")
BROWSER = shutil.which("chromium") or shutil.which("chromium-browser")
if not BROWSER:
    print("SKIP: chromium is missing; install the Debian package chromium")
    sys.exit(77)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def read_png(path):
    """(width, height, rows of (r, g, b)) of an 8-bit RGB or RGBA non-interlaced PNG"""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, (depth, colour, interlace)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def shoot(page, t, png, size="900,500"):
    url = "file://" + os.path.abspath(page) + f"?t={t}"
    subprocess.run([BROWSER, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
                    "--enable-unsafe-swiftshader", "--hide-scrollbars", f"--window-size={size}",
                    "--virtual-time-budget=5000", f"--screenshot={png}", url],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
    return read_png(png)


def blue(p):    # block A: the first colour of the palette, 0x1f77b4, shaded
    r, g, b = p
    return b > 90 and b > r + 40 and b > g + 10


def grey(p):    # the fixed block: 0x9a9a9a shaded, darker than the background 0xf4f4f0
    r, g, b = p
    return max(r, g, b) - min(r, g, b) < 8 and 60 < r < 200


# the controls (a blue slider) and the view labels take the top ~55 px; the canvases start below
CANVAS_TOP = 60


def blue_rows(rows, x0=0, x1=None):
    """(count, mean row) of the blue pixels of the canvases in columns [x0, x1)"""
    n = s = 0
    for y, row in enumerate(rows):
        if y < CANVAS_TOP:
            continue
        for p in row[x0:x1]:
            if blue(p):
                n, s = n + 1, s + y
    return n, (s / n if n else -1)


os.makedirs(SCRATCH, exist_ok=True)
runs = {}
for backend in ("dem", "dem-deformable"):
    out = os.path.join(SCRATCH, backend)
    shutil.rmtree(out, ignore_errors=True)
    extra = ["--model", "deformable"] if backend.endswith("deformable") else []
    r = subprocess.run([CAIRN, "run", "paper/impact", "-b", "dem", "-o", out, "--replay", "-q",
                        "--set", "run.duration=0.15", *extra], capture_output=True, text=True)
    if r.returncode == 2 and "built without the 3-D replay" in r.stderr:
        print("SKIP: " + r.stderr.strip())
        sys.exit(77)
    check(r.returncode == 0, f"cairn run --replay failed: {r.stderr}")
    if r.returncode != 0:
        sys.exit(1)
    runs[backend] = out

# one run at t = 0 and at t = 0.14 s: A fell 0.1 m (g t²/2 = 0.096 m) onto B
page = os.path.join(runs["dem"], "replay.html")
w, h, a = shoot(page, 0.0, os.path.join(SCRATCH, "dem_t0.png"))
_, _, b = shoot(page, 0.14, os.path.join(SCRATCH, "dem_t014.png"))
na, ya = blue_rows(a)
nb, yb = blue_rows(b)
greys = sum(grey(p) for row in a[CANVAS_TOP:] for p in row)
# a 1 m cube in a 900x360 view fitted to 2.1 m of blocks covers tens of thousands of pixels;
# 2000 is far below that and far above stray anti-aliasing
check(na > 2000 and nb > 2000, f"block A drawn with {na} and {nb} pixels")
check(greys > 2000, f"fixed block B drawn with {greys} pixels")
changed = sum(pa != pb for ra, rb in zip(a, b) for pa, pb in zip(ra, rb))
check(changed > 500, f"only {changed} pixels differ between t = 0 and t = 0.14 s")
# the image's rows grow downwards: A's pixels must sit lower at t = 0.14 s
check(yb > ya + 5, f"block A did not move down on screen (mean row {ya:.1f} -> {yb:.1f})")

# two runs side by side: each half of the page draws its own cube
page = os.path.join(SCRATCH, "side_by_side.html")
subprocess.run([CAIRN, "replay", runs["dem"], runs["dem-deformable"], "-o", page], check=True)
w, h, two = shoot(page, 0.05, os.path.join(SCRATCH, "side_by_side_t005.png"), size="1000,480")
left, _ = blue_rows(two, 0, w // 2)
right, _ = blue_rows(two, w // 2, w)
check(left > 1000 and right > 1000, f"side by side: {left} blue pixels on the left, {right} on the right")

print(f"{0 if failures else 1} passed, {1 if failures else 0} failed")
sys.exit(1 if failures else 0)

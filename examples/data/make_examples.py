#!/usr/bin/env python3
"""Writes the bundled example tows (run from this folder: python3 make_examples.py).

- straight_tube.stw: a circular tube, radius 0.5, length 4, 21 sections x 24 points
  (the accuracy case of the test suite: its exact volume is pi r^2 L = 3.14159...).
- warp_1.stw, weft_1.stw: two crimped lenticular-ish tows of a plain weave crossing each other,
  60 sections x 32 points, elliptical sections 1.0 x 0.25, following a cosine crimp.
"""
import math


def write(path, name, sections, comment):
    with open(path, "w") as f:
        f.write(f"# {comment}\n")
        f.write(f"tow {name}\n")
        for i, sec in enumerate(sections):
            if i:
                f.write("\n")
            for p in sec:
                f.write("%.12g %.12g %.12g\n" % p)


def tube():
    r, length, m, n = 0.5, 4.0, 21, 24
    secs = []
    for i in range(m):
        x = length * i / (m - 1)
        secs.append([(x, r * math.cos(2 * math.pi * j / n), r * math.sin(2 * math.pi * j / n)) for j in range(n)])
    return secs


def crimped(axis, phase, m=60, n=32, length=4.0, a=0.5, b=0.125, amp=0.1, wavelength=2.0):
    """A tow along x (axis=0) or y (axis=1) whose centre line is z = amp*cos(2 pi s/wavelength + phase)."""
    secs = []
    for i in range(m):
        s = -length / 2 + length * i / (m - 1)
        zc = amp * math.cos(2 * math.pi * s / wavelength + phase)
        dz = -amp * 2 * math.pi / wavelength * math.sin(2 * math.pi * s / wavelength + phase)
        # section in the plane normal to the centre line's tangent (t = (1, dz) in the s-z plane)
        tn = math.hypot(1.0, dz)
        ns, nz = -dz / tn, 1.0 / tn  # in-plane normal of the centre line
        sec = []
        for j in range(n):
            th = 2 * math.pi * j / n
            w, h = a * math.cos(th), b * math.sin(th)
            ds, z = s + h * ns, zc + h * nz
            if axis == 0:
                sec.append((ds, w, z))
            else:
                sec.append((-w, ds, z))
        secs.append(sec)
    return secs


if __name__ == "__main__":
    write("straight_tube.stw", "straight_tube", tube(), "circular tube r=0.5 L=4, 21 sections x 24 points")
    write("warp_1.stw", "warp_1", crimped(0, 0.0), "plain-weave warp: elliptical 1.0 x 0.25, crimp amplitude 0.1")
    write("weft_1.stw", "weft_1", crimped(1, math.pi), "plain-weave weft: elliptical 1.0 x 0.25, crimp amplitude 0.1")

#!/usr/bin/env python3
"""Writes the bundled example tows (run from this folder: python3 make_examples.py).

- straight_tube.stw: a circular tube, radius 0.5, length 4, 21 sections x 24 points
  (the accuracy case of the test suite: its exact volume is pi r^2 L = 3.14159...).
The woven example (twill/) is made by towgeom's own generator; see README.md here.
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


if __name__ == "__main__":
    write("straight_tube.stw", "straight_tube", tube(), "circular tube r=0.5 L=4, 21 sections x 24 points")

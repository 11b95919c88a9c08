#!/usr/bin/env python3
"""Writes the seeded regression inputs of both fuzz targets and their manifests (run from this
folder): stack_reader/ and stack_fit/ get the same files, each TARGET/expected.txt one line per
file, "FILE valid" or "FILE CODE LINE" (CODE as towgeom::errorCodeName(), LINE 1-based, 0 when
none). tests/test_fuzz_replay.cpp replays every file and asserts exactly that outcome: a valid
file is read, validated, round-trips through writeStack and fits in every mode with finite,
positive volumes and areas; any other is refused with that towgeom::Error.

They are variants of what once broke the reader or the fit (git log: NaN and Inf tokens, 1e400
and beyond-1e150 overflow, underflow to 0, +- tokens, a 70 000-character line, binary junk,
old Mac line ends, figure-eight sections, a tow bent through 350 degrees whose orientation was
once misjudged), not copies of the malformed matrix (tests/data/malformed, already seeds).
A crash the fuzzers find later goes in the folder of the target it broke, with its line in that
folder's expected.txt (re-running this script keeps such lines).
"""
import math
import os
import random

cases = []  # (name, expected) with expected "valid" or "CODE LINE"


def tube(m=6, n=12, r=1.0):
    return [[(0.5 * i, r * math.cos(2 * math.pi * j / n), r * math.sin(2 * math.pi * j / n)) for j in range(n)]
            for i in range(m)]


def render(sections, fmt="%.17g %.17g %.17g", header=("# fuzz regression", "tow regression")):
    """The file's lines and, for every point, its 1-based line number."""
    lines, where = list(header), []
    for i, sec in enumerate(sections):
        if i:
            lines.append("")
        row = []
        for p in sec:
            lines.append(fmt % p)
            row.append(len(lines))
        where.append(row)
    return lines, where


def write(name, data, expected):
    for target in ("stack_reader", "stack_fit"):
        with open(os.path.join(target, name), "wb") as f:
            f.write(data)
    cases.append((name, expected))


def text(lines, end="\n"):
    return (end.join(lines) + end).encode()


def with_line(i, j, replacement, code, sections=None):
    """A tube whose point (i, j) is replaced by @p replacement; refused with CODE at that line."""
    lines, where = render(sections or tube())
    lines[where[i][j] - 1] = replacement
    return text(lines), "%s %d" % (code, where[i][j])


for d in ("stack_reader", "stack_fit"):
    os.makedirs(d, exist_ok=True)

# NaN and infinity in the spellings from_chars accepts.
write("nan_spellings.stw", *with_line(2, 5, "1.0 NaN -nan", "non_finite"))
write("infinity_word.stw", *with_line(4, 0, "2.0 -Infinity 0", "non_finite"))
# Overflow: beyond the double range, and just beyond the reader's limit of 1e150.
write("exponent_overflow.stw", *with_line(5, 11, "2.5 -1e400 0", "out_of_range"))
write("beyond_limit.stw", *with_line(1, 3, "0.5 1.0000000001e150 0", "out_of_range"))
# Underflow reads as the nearest value (0 or a denormal): a valid tube.
lines, where = render(tube())
lines[where[0][0] - 1] = "0 1 1e-400"
lines[where[3][6] - 1] = "1.5 -1 -4.9e-325"
write("underflow_valid.stw", text(lines), "valid")
# A sign then another sign.
write("sign_sign.stw", *with_line(3, 2, "1.5 -+0.5 0.8", "non_numeric"))
# A 70 000-character line (over the 65536 limit), and a valid file with a 60 000-digit number.
write("long_line.stw", *with_line(2, 1, "1.0 0.8660254037844386 0." + "5" * 70000, "line_too_long"))
lines, where = render(tube())
lines[where[1][0] - 1] = "0.5 1." + "0" * 60000 + " 0"
write("long_number_valid.stw", text(lines), "valid")
# Binary junk after valid points (a NUL on line 20), and old Mac line ends (CR only).
lines, where = render(tube())
data = text(lines[:where[1][8]]) + b"\x00\x89PNG\r\n\x1a\n" + random.Random(11).randbytes(512)
write("binary_junk.stw", data, "binary_data %d" % (where[1][8] + 1))
lines, _ = render(tube())
write("cr_line_ends.stw", text(lines, "\r"), "binary_data 1")
# Figure-eight sections: the last section crosses itself (the middle of a 12-gon swapped).
eight = tube()
eight[5] = eight[5][:3] + eight[5][3:9][::-1] + eight[5][9:]
lines, where = render(eight)
write("figure_eight_last.stw", text(lines), "self_intersecting_section %d" % where[5][0])
# A tow bent through 350 degrees about z, its radius growing from 0.2 to 0.45 (orientation from
# local section votes: a global vote once reversed it), with a BOM, CRLF and commas.
m, n, bend, sweep = 61, 16, 2.0, math.radians(350.0)
sections = []
for i in range(m):
    phi = sweep * i / (m - 1)
    r = 0.2 + 0.25 * i / (m - 1)
    c = (bend * math.cos(phi), bend * math.sin(phi))
    sections.append([(c[0] + r * math.cos(t) * math.cos(phi), c[1] + r * math.cos(t) * math.sin(phi), r * math.sin(t))
                     for t in (2 * math.pi * j / n for j in range(n))])
lines, _ = render(sections, fmt="%.12g, %.12g, %.12g", header=("\ufeff# bent through 350 degrees", "tow bent_350"))
write("bent_350_valid.stw", text(lines, "\r\n"), "valid")

# expected.txt: this script's lines, then the lines of inputs added by hand (kept).
ours = {name for name, _ in cases}
for target in ("stack_reader", "stack_fit"):
    path = os.path.join(target, "expected.txt")
    kept = []
    if os.path.exists(path):
        with open(path) as f:
            kept = [line for line in f if line.split() and line.split()[0] not in ours]
    with open(path, "w") as f:
        for name, expected in cases:
            f.write("%s %s\n" % (name, expected))
        f.writelines(kept)

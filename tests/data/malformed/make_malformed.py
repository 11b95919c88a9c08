#!/usr/bin/env python3
"""Writes the malformed-input matrix and its manifest cases.txt (run from this folder).

Each case starts from a valid tube (5 sections x 8 points) and breaks one rule. cases.txt holds
one line per case: FILE CODE LINE, where CODE is towgeom::errorCodeName() of the expected error
and LINE the expected line number (0: no line, e.g. a missing file).
"""
import math
import os
import random

N, M = 8, 5


def tube(m=M, n=N):
    return [[(float(i), math.cos(2 * math.pi * j / n), math.sin(2 * math.pi * j / n)) for j in range(n)] for i in range(m)]


def render(sections, header=("# malformed-input case", "tow case")):
    """Returns the file's lines and, for every point, its 1-based line number."""
    lines, where = list(header), []
    for i, sec in enumerate(sections):
        if i:
            lines.append("")
        row = []
        for p in sec:
            lines.append(p if isinstance(p, str) else "%.17g %.17g %.17g" % p)
            row.append(len(lines))
        where.append(row)
    return lines, where


cases = []


def case(name, code, sections=None, edit=None, line_of=None, raw=None):
    if raw is not None:
        with open(name, "wb") as f:
            f.write(raw)
        cases.append((name, code, line_of or 0))
        return
    lines, where = render(sections if sections is not None else tube())
    line = 0
    if edit:
        line = edit(lines, where) or 0
    with open(name, "w") as f:
        f.write("\n".join(lines) + "\n")
    cases.append((name, code, line))


def set_line(i, j, text):
    def edit(lines, where):
        lines[where[i][j] - 1] = text
        return where[i][j]
    return edit


case("empty.stw", "empty_input", raw=b"")
case("comments_only.stw", "empty_input", raw=b"# nothing here\n# at all\n")
case("non_numeric.stw", "non_numeric", edit=set_line(2, 3, "2.0 abc 0.5"))
case("two_coordinates.stw", "wrong_coordinate_count", edit=set_line(1, 4, "1.0 0.5"))
case("four_coordinates.stw", "wrong_coordinate_count", edit=set_line(3, 0, "3.0 1.0 0.0 7.0"))
case("nan.stw", "non_finite", edit=set_line(2, 5, "2.0 nan 0.1"))
case("inf.stw", "non_finite", edit=set_line(4, 1, "4.0 0.7 -inf"))
case("huge.stw", "out_of_range", edit=set_line(1, 2, "1.0 1e300 0.0"))
case("overflow.stw", "out_of_range", edit=set_line(0, 2, "0.0 1e400 0.0"))


def drop_point(lines, where):
    del lines[where[3][7] - 1]
    return where[3][0]


case("unequal_points.stw", "unequal_section_size", edit=drop_point)
case("one_section.stw", "too_few_sections", sections=tube(m=1))
case("three_sections.stw", "too_few_sections", sections=tube(m=3))
case("five_points.stw", "too_few_points", sections=tube(n=5))
dup = tube()
dup[2][4] = dup[2][3]
case("duplicate_point.stw", "duplicate_point", sections=dup, line_of=None)
flat = tube()
flat[1] = [(1.0, -1.0 + 2.0 * j / (N - 1), 0.0) for j in range(N)]
case("zero_area.stw", "zero_area_section", sections=flat)
eight = tube()
eight[3] = [(3.0, 1.0, 0.0), (3.0, 0.6, 0.6), (3.0, 0.0, 0.0), (3.0, -0.6, -0.6), (3.0, -1.0, 0.0),
            (3.0, -0.6, 0.6), (3.0, 0.0, 0.1), (3.0, 0.6, -0.6)]
case("figure_eight.stw", "self_intersecting_section", sections=eight)
flipped = tube()
flipped[2] = [flipped[2][0]] + flipped[2][1:][::-1]
case("flipped_section.stw", "inconsistent_orientation", sections=flipped)
rep = tube()
rep[2] = list(rep[1])
case("repeated_section.stw", "degenerate_tow", sections=rep)
case("binary.stw", "binary_data", raw=b"# header\n0 1 0\n\x00\x01\x02\xff\xfe junk\n")
# Binary junk from the first byte: a gzip header and 4 KiB of (seeded) random bytes.
case("junk.stw", "binary_data", raw=b"\x1f\x8b\x08\x00" + random.Random(6).randbytes(4096), line_of=1)
case("bad_name.stw", "bad_name", edit=lambda lines, where: (lines.__setitem__(1, "tow ../../etc/passwd"), 2)[1])


def name_late(lines, where):
    lines.insert(where[1][0] - 1, "tow late_name")
    return where[1][0]


case("name_after_points.stw", "bad_name", edit=name_late)
# A section's first point may sit anywhere around the tow (fit renumbers it), but a flat tow
# whose third section is turned across (a section from another place) matches the second under
# no renumbering.
def flat_tube(m=M, n=N, a=1.0, b=0.15):
    return [[(float(i), a * math.cos(2 * math.pi * j / n), b * math.sin(2 * math.pi * j / n)) for j in range(n)]
            for i in range(m)]


foreign = flat_tube()
foreign[2] = [(x, -z, y) for (x, y, z) in foreign[2]]  # turned by 90 degrees about x
case("foreign_section.stw", "inconsistent_start", sections=foreign)
case("plus_minus.stw", "non_numeric", edit=set_line(1, 1, "1.0 +-0.5 0.2"))
case("long_name.stw", "bad_name", edit=lambda lines, where: (lines.__setitem__(1, "tow " + "n" * 201), 2)[1])
case("long_line.stw", "line_too_long", edit=set_line(3, 2, "3.0 0.5 " + "0" * 70000))
cases.append(("missing.stw", "file_not_found", 0))
os.makedirs("directory.stw", exist_ok=True)
open(os.path.join("directory.stw", ".keep"), "w").close()
cases.append(("directory.stw", "file_unreadable", 0))

# Lines that depend on the rule's own report: fix them up from the rendered tubes.
fix = {
    "duplicate_point.stw": render(dup)[1][2][4],
    "zero_area.stw": render(flat)[1][1][0],
    "figure_eight.stw": render(eight)[1][3][0],
    "flipped_section.stw": render(flipped)[1][2][0],
    "repeated_section.stw": render(rep)[1][2][0],
    "foreign_section.stw": render(foreign)[1][2][0],
    "one_section.stw": render(tube(m=1))[1][0][0],
    "three_sections.stw": render(tube(m=3))[1][2][0],
    "five_points.stw": render(tube(n=5))[1][0][0],
    "binary.stw": 3,
    "comments_only.stw": 0,
    "empty.stw": 0,
}
with open("cases.txt", "w") as f:
    for name, code, line in cases:
        f.write("%s %s %d\n" % (name, code, fix.get(name, line)))

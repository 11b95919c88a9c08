#!/usr/bin/env python3
"""Chooses the sanitized tier by measurement: which tests the sanitizer stage must run so that every
line of towgeom's code that the whole suite runs still runs under ASan+UBSan.

Runs every test the sanitizer stage could run (not labelled skip-sanitize), one at a time, in the
coverage build (tests/sanitizer/measure_coverage.sh builds it: g++ -O1 --coverage), each with
its own GCOV_PREFIX so two run at once, and reads with gcov which lines of src/ and include/ each
one executed. Then a greedy weighted set cover, the cost of a test being its time under the
sanitizers (from a sanitized run's CTest log; tests missing from it are estimated from their
coverage-build time): every test cheaper than --keep-below seconds stays, then the test that
adds the most not yet covered lines per second is taken, until the selection covers every line
any test covers; last, a costly test whose lines the others cover after all is dropped. The tests left out (each costly, and each line of it run by a test that stays)
are written to tests/sanitizer/not_sanitized.txt with, for each, its sanitized time and the
tests that run its lines.

Not part of the test command (it runs the suite once per test in another build); run it after
adding costly tests:
    bash tests/sanitizer/measure_coverage.sh          # builds build-coverage/
    python3 tests/sanitizer/select_by_coverage.py --costs build-sanitize/Testing/Temporary/LastTest.log
"""
import argparse
import concurrent.futures
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def tests_of(build):
    """(number, name) of every test the sanitizer stage could run, in CTest's numbering."""
    listing = json.loads(subprocess.run(["ctest", "--test-dir", str(build), "--show-only=json-v1"],
                                        check=True, capture_output=True, text=True).stdout)
    result = []
    for number, test in enumerate(listing["tests"], start=1):
        labels = [p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"]
        if any("skip-sanitize" in (v if isinstance(v, list) else [v]) for v in labels):
            continue
        result.append((number, test["name"]))
    return result


def gcov_lines(prefix_dir, build):
    """{(source, line)} executed, from the .gcda files under prefix_dir (GCOV_PREFIX of one run)."""
    # The library's and the CLI's objects only: the tests' own (Catch, the oracles) are not
    # what the sanitizers are there for, and their reports are large.
    gcdas = [p for p in pathlib.Path(prefix_dir).rglob("*.gcda")
             if any(part in ("towgeom_objects.dir", "towgeom_cli.dir") for part in p.parts)]
    if not gcdas:
        return set()
    stripped = str(pathlib.Path(prefix_dir))
    for gcda in gcdas:  # the notes file next to each data file, as gcov wants them
        original = pathlib.Path(str(gcda)[len(stripped):]).with_suffix(".gcno")
        link = gcda.with_suffix(".gcno")
        if original.exists() and not link.exists():
            link.symlink_to(original)
    lines = set()
    roots = (str(ROOT / "src") + "/", str(ROOT / "include") + "/")
    # gcov -t -j prints one JSON document per data file on its own line; -s ROOT -r keeps only
    # the sources under ROOT (not the engines' and the standard library's headers).
    out = subprocess.run(["gcov", "-t", "-j", "-s", str(ROOT), "-r", *map(str, gcdas)], capture_output=True,
                         text=True, cwd=str(build)).stdout
    for text in out.splitlines():
        text = text.strip()
        if not text.startswith("{"):
            continue
        doc = json.loads(text)
        for f in doc.get("files", []):
            source = os.path.normpath(os.path.join(str(ROOT), f["file"]))
            if not source.startswith(roots):
                continue
            rel = os.path.relpath(source, ROOT)
            for line in f.get("lines", []):
                if line.get("count", 0) > 0:
                    lines.add((rel, line["line_number"]))
    return lines


def run_one(build, number, name, scratch):
    prefix = pathlib.Path(scratch) / str(number)
    env = dict(os.environ, GCOV_PREFIX=str(prefix), GCOV_PREFIX_STRIP="0")
    start = time.monotonic()
    run = subprocess.run(["ctest", "--test-dir", str(build), "-I", f"{number},{number}", "--output-on-failure"],
                         env=env, capture_output=True, text=True)
    seconds = time.monotonic() - start
    lines = gcov_lines(prefix, build)
    shutil.rmtree(prefix, ignore_errors=True)
    return number, name, run.returncode == 0, seconds, lines


def sanitized_costs(log):
    """{test name: seconds} from a CTest LastTest.log."""
    costs, name = {}, None
    for text in pathlib.Path(log).read_text(errors="replace").splitlines():
        m = re.match(r"^\d+/\d+ Test: (.*)$", text)
        if m:
            name = m.group(1)
        m = re.match(r"^Test time =\s*([0-9.]+) sec", text)
        if m and name is not None:
            costs[name] = float(m.group(1))
            name = None
    return costs


def measure(build, jobs, cache, keep=None, again=()):
    """Measures every test, or with @p keep (an earlier measurement) only the tests it lacks and
    those whose names contain one of @p again; returns all, and writes them to @p cache."""
    tests = tests_of(build)
    names = {name for _, name in tests}
    measured = {n: m for n, m in (keep or {}).items() if n in names and not any(a in n for a in again)}
    tests = [(n, name) for n, name in tests if name not in measured]
    with tempfile.TemporaryDirectory(prefix="towgeom-cov-") as scratch, \
            concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(run_one, build, n, name, scratch) for n, name in tests]
        for done, future in enumerate(concurrent.futures.as_completed(futures), start=1):
            number, name, ok, seconds, lines = future.result()
            measured[name] = {"ok": ok, "seconds": seconds, "lines": sorted(lines)}
            print(f"[{done}/{len(tests)}] {seconds:6.1f} s {len(lines):6d} lines {'' if ok else 'FAILED '}{name}",
                  file=sys.stderr, flush=True)
    cache.write_text(json.dumps(measured))
    return measured


def select(measured, costs, keep_below):
    """Greedy weighted set cover; returns (kept, left out, cost of each)."""
    known = [(costs[n], m["seconds"]) for n, m in measured.items() if n in costs and m["seconds"] > 0]
    ratios = sorted(c / s for c, s in known) or [10.0]
    scale = ratios[len(ratios) // 2]
    cost = {n: costs.get(n, m["seconds"] * scale) for n, m in measured.items()}
    lines = {n: set(map(tuple, m["lines"])) for n, m in measured.items()}
    universe = set().union(*lines.values())
    kept = {n for n in measured if cost[n] < keep_below}
    covered = set().union(*(lines[n] for n in kept)) if kept else set()
    while covered != universe:
        best = max((n for n in measured if n not in kept),
                   key=lambda n: (len(lines[n] - covered) / max(cost[n], 0.01), -cost[n]))
        kept.add(best)
        covered |= lines[best]
    # Then the other way: a costly test whose lines the rest now cover (a greedy pick made
    # redundant by later ones) goes, the costliest first.
    for name in sorted((n for n in kept if cost[n] >= keep_below), key=lambda n: -cost[n]):
        rest = set().union(*(lines[k] for k in kept if k != name))
        if lines[name] <= rest:
            kept.remove(name)
    return kept, set(measured) - kept, cost, lines, universe


def write_list(path, left_out, kept, cost, lines, universe, keep_below, within=None):
    total = sum(cost.values())
    kept_cost = sum(cost[n] for n in kept)
    if within is None:
        scope = [
            "# test cheaper than %g s under ASan+UBSan stays; of the others, a greedy weighted set cover" % keep_below,
            "# keeps the fewest sanitized seconds that still run every line of src/ and include/ that the",
            "# whole suite runs (gcov, one test at a time). Each test below runs in Release as before, and",
            "# each line of its code also runs in the sanitized tests named under it.",
            "# Measured: %d lines run by the suite, all of them by the %d tests kept (%.0f s of the"
            % (len(universe), len(kept), kept_cost),
        ]
    else:
        scope = [
            "# list was narrowed (--within): only tests the list before left in could stay; of those, every",
            "# test cheaper than %g s under ASan+UBSan stays, and a costly one went where the others kept" % keep_below,
            "# run all its lines (gcov, one test at a time). So every line the sanitized tests ran before",
            "# still runs in them. The tests left out before are listed last, as they were (their lines",
            "# are not all run sanitized: a full run of this script would bring some back).",
            "# Measured: %d lines run by the tests allowed, all of them by the %d tests kept (%.0f s of the"
            % (len(universe), len(kept), kept_cost),
        ]
    out = [
        "# Tests the sanitizer stage (tests/run_sanitized.sh) does not run, one CTest name per line.",
        "# Written by tests/sanitizer/select_by_coverage.py (do not edit by hand; run it again): every" if within is None else
        "# Written by tests/sanitizer/select_by_coverage.py (do not edit by hand; run it again). The",
        *scope,
        "# %.0f s all would take sanitized, summed over tests)." % total,
        "#",
    ]
    for name in sorted(left_out, key=lambda n: -cost[n]):
        if within is not None and name in within:
            continue
        mine = lines[name]
        covers = sorted(kept, key=lambda k: -len(mine & lines[k]))
        names = []
        rest = set(mine)
        for k in covers:
            if not rest:
                break
            if rest & lines[k]:
                names.append(k)
                rest -= lines[k]
        shown = "; ".join('"%s"' % k for k in names[:3]) + (" and %d more" % (len(names) - 3) if len(names) > 3 else "")
        out.append("# %.0f s sanitized, %d lines, all run by: %s" % (cost[name], len(mine), shown))
        out.append(name)
    if within is not None:
        out.append("#")
        out.append("# Left out by the list before (--within), kept out:")
        out.extend(sorted(within, key=lambda n: -cost.get(n, 0.0)))
    pathlib.Path(path).write_text("\n".join(out) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build-coverage"), help="the coverage build (built)")
    parser.add_argument("--costs", required=True, help="LastTest.log of a sanitized CTest run")
    parser.add_argument("--keep-below", type=float, default=5.0, help="seconds sanitized under which a test always stays")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--reuse", action="store_true",
                        help="reuse the last measurement (BUILD/coverage_per_test.json); measure only tests it lacks")
    parser.add_argument("--again", action="append", default=[],
                        help="with --reuse, measure again the tests whose names contain this text (repeatable)")
    parser.add_argument("--out", default=str(ROOT / "tests" / "sanitizer" / "not_sanitized.txt"))
    parser.add_argument("--within", help="a not_sanitized.txt: its tests stay left out, and only the lines the "
                                         "others run need to stay covered (narrows a list without a full run's costs)")
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    cache = build / "coverage_per_test.json"
    earlier = json.loads(cache.read_text()) if args.reuse and cache.exists() else None
    measured = measure(build, args.jobs, cache, earlier, args.again)
    failed = [n for n, m in measured.items() if not m["ok"]]
    if failed:
        print("select_by_coverage: tests failed in the coverage build (their lines still count):\n  " +
              "\n  ".join(failed), file=sys.stderr)
    within = None
    if args.within:
        within = {line for line in pathlib.Path(args.within).read_text().splitlines() if line and not line.startswith("#")}
        allowed = {n: m for n, m in measured.items() if n not in within}
        within &= set(measured)
        kept, left_out, cost, lines, universe = select(allowed, sanitized_costs(args.costs), args.keep_below)
        _, _, all_cost, _, _ = select(measured, sanitized_costs(args.costs), args.keep_below)
        cost = all_cost
        lines = {n: set(map(tuple, m["lines"])) for n, m in measured.items()}
        left_out = left_out | within
    else:
        kept, left_out, cost, lines, universe = select(measured, sanitized_costs(args.costs), args.keep_below)
    write_list(args.out, left_out, kept, cost, lines, universe, args.keep_below, within)
    print("select_by_coverage: %d lines; %d tests kept (%.0f s sanitized), %d left out (%.0f s); wrote %s" %
          (len(universe), len(kept), sum(cost[n] for n in kept), len(left_out), sum(cost[n] for n in left_out), args.out))


if __name__ == "__main__":
    main()

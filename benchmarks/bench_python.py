#!/usr/bin/env python3
"""The Python module's overhead: resolve_textile() called from Python against the same call made
and timed in C++ alone (towgeom._towgeom._resolve_seconds_in_cpp), side by side, on the bundled
twill at several mesh sizes. Run with the build's package on the path:

    PYTHONPATH=build/python python3 benchmarks/bench_python.py [--repeat 5]
"""

import argparse
import pathlib
import time

import towgeom
from towgeom import _towgeom


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=5, help="calls of each, interleaved; the least time of each is kept")
    parser.add_argument("--threads", type=int, default=0, help="threads of each call (0: all)")
    parser.add_argument("--sizes", default="0.2,0.1,0.05", help="mesh sizes (edge lengths), comma-separated")
    args = parser.parse_args()
    data = pathlib.Path(__file__).resolve().parents[1] / "examples" / "data" / "twill"
    tows = [towgeom.TowSurface.fit(towgeom.read_stack(str(p))) for p in sorted(data.glob("*.stw"))]
    report = towgeom.intersect_tows(tows)
    print(f"threads {args.threads}; least of {args.repeat} calls each, interleaved")
    print(f"{'mesh size':>10} {'nodes':>8} {'wall: Python s':>15} {'C++ s':>7} {'ratio':>6} {'CPU: Python s':>14} {'C++ s':>7} {'ratio':>6}")
    for size in map(float, args.sizes.split(",")):
        options = towgeom.ResolveOptions(edge_length=size, threads=args.threads)
        wall, cpu, nodes = ([], []), ([], []), 0
        for _ in range(args.repeat):
            start, start_cpu = time.perf_counter(), time.process_time()
            result = towgeom.resolve_textile(tows, report, options)
            nodes = len(result.mesh.nodes)
            del result  # dropped inside the timing, as the C++ side's
            wall[0].append(time.perf_counter() - start)
            cpu[0].append(time.process_time() - start_cpu)
            start_cpu = time.process_time()
            wall[1].append(_towgeom._resolve_seconds_in_cpp(tows, report, options))
            cpu[1].append(time.process_time() - start_cpu)
        w, c = [min(x) for x in wall], [min(x) for x in cpu]
        print(f"{size:>10g} {nodes:>8} {w[0]:>15.3f} {w[1]:>7.3f} {w[0] / w[1]:>6.3f} {c[0]:>14.3f} {c[1]:>7.3f} {c[0] / c[1]:>6.3f}")


if __name__ == "__main__":
    main()

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
    parser.add_argument("--sizes", default="0.2,0.1,0.05", help="mesh sizes (edge lengths), comma-separated")
    args = parser.parse_args()
    data = pathlib.Path(__file__).resolve().parents[1] / "examples" / "data" / "twill"
    tows = [towgeom.TowSurface.fit(towgeom.read_stack(str(p))) for p in sorted(data.glob("*.stw"))]
    report = towgeom.intersect_tows(tows)
    print(f"{'mesh size':>10} {'nodes':>8} {'Python s':>9} {'C++ s':>9} {'ratio':>6}")
    for size in map(float, args.sizes.split(",")):
        options = towgeom.ResolveOptions(edge_length=size)
        from_python, in_cpp, nodes = [], [], 0
        for _ in range(args.repeat):
            start = time.perf_counter()
            result = towgeom.resolve_textile(tows, report, options)
            from_python.append(time.perf_counter() - start)
            nodes = len(result.mesh.nodes)
            del result
            in_cpp.append(_towgeom._resolve_seconds_in_cpp(tows, report, options))
        print(f"{size:>10g} {nodes:>8} {min(from_python):>9.3f} {min(in_cpp):>9.3f} {min(from_python) / min(in_cpp):>6.3f}")


if __name__ == "__main__":
    main()

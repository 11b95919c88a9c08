"""The Python module adds less than 5 % to the C++ call's time on the bundled twill's resolve
(benchmarks/bench_python.py prints the same comparison at several sizes)."""

import time

import towgeom
from towgeom import _towgeom


def test_resolve_from_python_costs_at_most_five_percent_more(twill_tows):
    report = towgeom.intersect_tows(twill_tows)
    options = towgeom.ResolveOptions(edge_length=0.1)
    from_python, in_cpp = [], []
    for _ in range(5):  # interleaved, the least of each: the machine's noise is larger than the overhead
        start = time.perf_counter()
        result = towgeom.resolve_textile(twill_tows, report, options)
        from_python.append(time.perf_counter() - start)
        del result
        in_cpp.append(_towgeom._resolve_seconds_in_cpp(twill_tows, report, options))
    print(f"resolve: {min(from_python):.3f} s from Python, {min(in_cpp):.3f} s in C++: ratio {min(from_python) / min(in_cpp):.3f}")
    assert min(from_python) <= 1.05 * min(in_cpp)

"""Errors raise towgeom.Error with the file and line; Ctrl-C stops a long stage within a second;
progress reaches a Python callable, and an exception raised there stops the work."""

import os
import signal
import threading
import time

import pytest

import towgeom


def test_a_bad_stack_file_raises_with_file_and_line(twill_paths, tmp_path):
    lines = twill_paths[0].read_text().splitlines()
    number = next(k for k, line in enumerate(lines) if line.strip() and line.split()[0][0] in "-0123456789") + 3
    lines[number - 1] = "0.1 zero 0.3"
    bad = tmp_path / "bad.stw"
    bad.write_text("\n".join(lines) + "\n")
    with pytest.raises(towgeom.Error) as caught:
        towgeom.read_stack(str(bad))
    assert caught.value.code == "non_numeric"
    assert caught.value.file == str(bad)
    assert caught.value.line == number
    assert isinstance(caught.value, RuntimeError)


def test_options_out_of_their_domain_raise():
    with pytest.raises(towgeom.Error) as caught:
        towgeom.ResolveOptions(method="fastest")
    assert caught.value.code == "invalid_argument" and "connect" in str(caught.value)
    with pytest.raises(TypeError, match="edge_lenght"):
        towgeom.ResolveOptions(edge_lenght=0.1)
    with pytest.raises(towgeom.Error) as caught:
        towgeom.generate_weave(kind="twill", width=-1.0)
    assert caught.value.code == "invalid_argument"


def test_keywords_reach_the_nested_options():
    options = towgeom.ResolveOptions(edge_length=0.2, tolerance=1e-6, method="symmetric", threads=1)
    assert options.mesh.edge_length == 0.2
    assert options.intersection.tolerance == 1e-6
    assert (options.method, options.threads) == ("symmetric", 1)


def test_ctrl_c_during_resolve_raises_within_a_second(twill_tows):
    sent = []

    def interrupt():
        time.sleep(0.5)
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    # A mesh fine enough to take several seconds (about 4 s on the 2-core machine).
    killer = threading.Thread(target=interrupt)
    killer.start()
    with pytest.raises(KeyboardInterrupt):
        towgeom.resolve_textile(twill_tows, edge_length=0.03)
    stopped = time.monotonic()
    killer.join()
    assert sent, "the resolve finished before the signal"
    assert stopped - sent[0] < 1.0


def test_progress_reaches_python_and_its_exception_stops_the_work(twill_tows):
    seen = []
    towgeom.intersect_tows(twill_tows, progress=lambda stage, done, total: seen.append((stage, done, total)))
    assert seen and all(done <= total for _, done, total in seen)

    class Enough(Exception):
        pass

    def stop(stage, done, total):
        raise Enough(stage)

    with pytest.raises(Enough):
        towgeom.resolve_textile(twill_tows, edge_length=0.1, progress=stop)

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


def test_errors_name_the_tow_they_are_about():
    textile = towgeom.generate_weave(kind="twill", warps=4, wefts=4, overlap=0.1)
    tows = [towgeom.TowSurface.fit(stack) for stack in textile.stacks()]
    # A periodic cell the 4 x 4 twill does not repeat with: refused, naming the first such tow.
    with pytest.raises(towgeom.Error) as caught:
        towgeom.resolve_textile(tows, cell=towgeom.Cell((0.5, 0.5, -1.0), (1.5, 1.5, 1.0), periodic=True))
    assert caught.value.code == "invalid_argument"
    assert caught.value.tow in textile.names and str(caught.value).startswith(f"tow '{caught.value.tow}'")
    assert caught.value.file is None


def test_ctrl_c_during_resolve_raises_within_a_second(twill_tows):
    """SIGINT sent (a real signal, as a terminal's Ctrl-C) when the meshing stage starts, from the
    progress callable: the KeyboardInterrupt must follow within a second."""
    sent = []

    def interrupt_when_meshing(stage, done, total):
        if not sent and stage.startswith("meshing tows"):
            sent.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)

    # A mesh fine enough to take several seconds (about 4 s on the 2-core machine).
    with pytest.raises(KeyboardInterrupt):
        towgeom.resolve_textile(twill_tows, edge_length=0.03, progress=interrupt_when_meshing)
    stopped = time.monotonic()
    assert sent, "the meshing stage never reported progress"
    assert stopped - sent[0] < 1.0


def test_progress_reaches_python_on_the_calling_thread_and_its_exception_stops_the_work(twill_tows):
    seen, threads = [], set()

    def record(stage, done, total):
        seen.append((stage, done, total))
        threads.add(threading.get_ident())

    towgeom.intersect_tows(twill_tows, progress=record)
    assert seen and all(done <= total for _, done, total in seen)
    assert threads == {threading.get_ident()}  # never on the library's threads

    class Enough(Exception):
        pass

    calls = []

    def stop(stage, done, total):
        calls.append(stage)
        raise Enough(stage)

    start = time.monotonic()
    towgeom.resolve_textile(twill_tows, edge_length=0.05)
    whole = time.monotonic() - start
    start = time.monotonic()
    with pytest.raises(Enough):
        towgeom.resolve_textile(twill_tows, edge_length=0.05, progress=stop)
    stopped = time.monotonic() - start
    assert len(calls) == 1  # no update after the exception
    assert stopped < 0.5 * whole  # the work was cancelled, not run to its end
    with pytest.raises(TypeError, match="progress"):
        towgeom.intersect_tows(twill_tows, progress=5)

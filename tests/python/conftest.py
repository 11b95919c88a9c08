"""Fixtures of the Python module's tests: the bundled twill, fitted once, and the C++ command-line
tool's own numbers for it (CTest passes TOWGEOM_CLI and TOWGEOM_EXAMPLE_DATA)."""

import json
import os
import pathlib
import subprocess

import pytest

import towgeom

EXAMPLE_DATA = pathlib.Path(os.environ.get("TOWGEOM_EXAMPLE_DATA", pathlib.Path(__file__).parents[2] / "examples" / "data"))
CLI = os.environ.get("TOWGEOM_CLI", "towgeom")
TWILL_MESH_SIZE = 0.1


@pytest.fixture(scope="session")
def twill_paths():
    paths = sorted((EXAMPLE_DATA / "twill").glob("*.stw"))
    assert len(paths) == 8
    return paths


@pytest.fixture(scope="session")
def twill_tows(twill_paths):
    return [towgeom.TowSurface.fit(towgeom.read_stack(str(p))) for p in twill_paths]


@pytest.fixture(scope="session")
def cli_twill_report(twill_paths, tmp_path_factory):
    """report.json of `towgeom resolve` on the twill with the same mesh size (the C++ side)."""
    out = tmp_path_factory.mktemp("cli_twill")
    subprocess.run([CLI, "resolve", *map(str, twill_paths), "--mesh-size", str(TWILL_MESH_SIZE), "--formats", "vtk",
                    "--out", str(out), "--quiet"], check=True)
    return json.loads((out / "report.json").read_text())


@pytest.fixture(scope="session")
def cli_twill_fit(twill_paths):
    """`towgeom fit`'s JSON for the twill's tows (the C++ side of the fit)."""
    done = subprocess.run([CLI, "fit", *map(str, twill_paths), "--quiet"], check=True, capture_output=True, text=True)
    return json.loads(done.stdout)["tows"]

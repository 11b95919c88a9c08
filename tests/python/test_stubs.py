"""The type stubs the build writes (towgeom/_towgeom.pyi) parse, and name every public function,
class and class member of the module."""

import ast
import inspect
import pathlib

from towgeom import _towgeom


def test_stubs_cover_the_module():
    stub_path = pathlib.Path(_towgeom.__file__).with_name("_towgeom.pyi")
    assert stub_path.with_name("py.typed").exists()
    tree = ast.parse(stub_path.read_text())
    top = {node.name: node for node in tree.body if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
    public = {name for name in vars(_towgeom) if not name.startswith("_") and callable(getattr(_towgeom, name))}
    assert public <= set(top), f"not in the stubs: {sorted(public - set(top))}"
    for name, value in vars(_towgeom).items():
        if name.startswith("_") or not inspect.isclass(value) or issubclass(value, Exception):
            continue
        stubbed = {node.name for node in top[name].body if isinstance(node, ast.FunctionDef)}
        members = {m for m in value.__dict__ if not m.startswith("_")}
        assert members <= stubbed, f"{name}: not in the stubs: {sorted(members - stubbed)}"

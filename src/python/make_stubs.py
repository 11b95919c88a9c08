#!/usr/bin/env python3
"""Writes the type stubs of the built extension towgeom._towgeom (towgeom/_towgeom.pyi) from the
signatures and docstrings pybind11 gives each function, method and property, and the marker
py.typed, into the package directory given. Run by the build after the extension is linked:

    make_stubs.py PACKAGE_DIR     (PACKAGE_DIR/.. on PYTHONPATH)
"""

import importlib
import inspect
import pathlib
import re
import sys
import textwrap

MODULE = "towgeom._towgeom"


def clean(text):
    """pybind11's qualified names as the stub spells them."""
    text = text.replace(MODULE + ".", "")
    text = text.replace("List[float[3]]", "Tuple[float, float, float]")
    text = text.replace("progress: object", "progress: Optional[Callable[[str, int, int], object]]")
    return re.sub(r"\bnumpy\.ndarray\[[^\]]*\]", "numpy.ndarray", text)


def split_doc(doc):
    """(signatures, description) of a pybind11 docstring: overloads list several signatures."""
    lines = (doc or "").strip().splitlines()
    signatures = [line for line in lines if re.match(r"^(\d+\. )?\w*\(.*\)( -> .*)?$", line)]
    body = [line for line in lines if line not in signatures and not line.startswith("Overloaded function")]
    return [re.sub(r"^\d+\. ", "", s) for s in signatures], "\n".join(body).strip()


def docstring(text, indent):
    if not text:
        return ""
    quoted = text.replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
    return textwrap.indent(f'"""{quoted}"""', indent) + "\n"


def function_stub(name, obj, indent="", static=False):
    signatures, body = split_doc(obj.__doc__)
    out = []
    for signature in signatures or [f"{name}(*args, **kwargs) -> object"]:
        params_and_result = clean(signature[signature.index("("):])
        if signature.startswith("(") or signature.startswith("__init__"):
            params_and_result = clean(signature[signature.index("("):])
        if len(signatures) > 1:
            out.append(f"{indent}@overload")
        if static:
            out.append(f"{indent}@staticmethod")
        params_and_result = re.sub(r"= <[^>]*>", "= ...", params_and_result)
        params_and_result = re.sub(r"= (None|[-+.\w']+)", "= ...", params_and_result)
        if params_and_result.startswith("(self") is False and not static and indent:
            params_and_result = "(self" + (", " if params_and_result[1] != ")" else "") + params_and_result[1:]
        out.append(f"{indent}def {name}{params_and_result}:")
        out.append(docstring(body, indent + "    ").rstrip("\n") or f"{indent}    ...")
        if body:
            out.append(f"{indent}    ...")
    return "\n".join(out)


def property_stub(name, prop, indent):
    signatures, body = split_doc(prop.fget.__doc__)
    result = clean(signatures[0].split(" -> ")[-1]) if signatures else "object"
    lines = [f"{indent}@property", f"{indent}def {name}(self) -> {result}:"]
    lines.append(docstring(body, indent + "    ").rstrip("\n") or f"{indent}    ...")
    if body:
        lines.append(f"{indent}    ...")
    if prop.fset is not None:
        lines += [f"{indent}@{name}.setter", f"{indent}def {name}(self, value: {result}) -> None: ..."]
    return "\n".join(lines)


def class_stub(name, cls):
    base = "RuntimeError" if issubclass(cls, Exception) else "object"
    lines = [f"class {name}({base}):", docstring(inspect.cleandoc(cls.__doc__ or ""), "    ").rstrip("\n")]
    if base == "RuntimeError":
        lines += ["    code: str", "    message: str", "    file: Optional[str]", "    line: Optional[int]"]
        return "\n".join(line for line in lines if line)
    for member, value in cls.__dict__.items():
        if member.startswith("_") and member not in ("__init__", "__len__"):
            continue
        if isinstance(value, property):
            lines.append(property_stub(member, value, "    "))
        elif isinstance(value, staticmethod):
            lines.append(function_stub(member, value.__func__, "    ", static=True))
        elif callable(value) and not (value.__doc__ or "").startswith("Initialize self"):
            lines.append(function_stub(member, value, "    "))
    return "\n".join(line for line in lines if line)


def main():
    package = pathlib.Path(sys.argv[1])
    here = pathlib.Path(__file__).resolve().parent  # holds the package's sources, without the extension
    sys.path[:] = [p for p in sys.path if pathlib.Path(p or ".").resolve() != here]
    module = importlib.import_module(MODULE)
    parts = ['"""Type stubs of towgeom._towgeom, written by src/python/make_stubs.py from the built module."""',
             "import os", "from typing import Any, Callable, Dict, List, Optional, Tuple, Union, overload", "import numpy", "",
             f"__version__: str", f"FACE_NAMES: Tuple[str, ...]", ""]
    for name, value in sorted(vars(module).items()):
        if name.startswith("__"):
            continue
        if inspect.isclass(value):
            parts.append(class_stub(name, value) + "\n")
        elif callable(value):
            parts.append(function_stub(name, value) + "\n")
    (package / "_towgeom.pyi").write_text("\n".join(parts))
    (package / "py.typed").write_text("")


if __name__ == "__main__":
    main()

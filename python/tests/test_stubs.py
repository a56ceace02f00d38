"""The type stubs (py.typed, __init__.pyi, dask.pyi) name every public function with the
parameters the package takes, every result class with its fields."""

import ast
import inspect
import pathlib

import moving_hertz as mh
import moving_hertz.dask as mhd

PKG = pathlib.Path(mh.__file__).parent


def _stubs(name):
    tree = ast.parse((PKG / name).read_text())
    funcs = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    return funcs, classes


def _params(node):
    a = node.args
    return [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]


def test_py_typed_ships():
    assert (PKG / "py.typed").exists()


def test_every_public_function_and_result_has_its_stub():
    funcs, classes = _stubs("__init__.pyi")
    for name in mh.__all__:
        obj = getattr(mh, name)
        if inspect.isfunction(obj):
            assert _params(funcs[name]) == list(inspect.signature(obj).parameters), name
            assert obj.__doc__ and len(obj.__doc__) > 80, name
        elif isinstance(obj, type) and hasattr(obj, "_fields"):
            stub_fields = [n.target.id for n in classes[name].body if isinstance(n, ast.AnnAssign)]
            assert stub_fields == list(obj._fields), name
        elif isinstance(obj, type):
            assert name in classes, name


def test_dask_stubs():
    funcs, _ = _stubs("dask.pyi")
    for name in mhd.__all__:
        assert _params(funcs[name]) == list(inspect.signature(getattr(mhd, name)).parameters)

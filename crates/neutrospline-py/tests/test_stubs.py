"""The type stubs (`_neutrospline.pyi`, shipped with `py.typed`) name every public function,
class and method of the module, with the runtime's parameter names."""

import ast
import inspect
import pathlib

import neutrospline
from neutrospline import _neutrospline

STUB = pathlib.Path(_neutrospline.__file__).with_name("_neutrospline.pyi")


def stub_tree():
    tree = ast.parse(STUB.read_text())
    functions = {}
    classes = {}
    names = set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            functions[node.name] = node
        elif isinstance(node, ast.ClassDef):
            classes[node.name] = {
                item.name: item for item in node.body if isinstance(item, ast.FunctionDef)
            }
            # Class attributes (`bezier: ClassVar[Type["BezierSurface"]]`).
            classes[node.name].update(
                (item.target.id, item)
                for item in node.body
                if isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name)
            )
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return functions, classes, names


def parameter_names(node):
    arguments = node.args
    names = [a.arg for a in arguments.posonlyargs + arguments.args + arguments.kwonlyargs]
    return [n for n in names if n != "self"]


def runtime_parameters(obj):
    signature = inspect.signature(obj)
    return [n for n in signature.parameters if n not in ("self", "cls")]


def test_the_stub_and_py_typed_ship_with_the_package():
    assert STUB.is_file()
    assert STUB.with_name("py.typed").is_file()


def test_every_public_name_is_in_the_stub():
    functions, classes, names = stub_tree()
    for name in neutrospline.__all__:
        assert name in functions or name in classes or name in names, name
    for name, obj in vars(_neutrospline).items():
        if inspect.isbuiltin(obj):
            assert name in functions, name
            stub, runtime = parameter_names(functions[name]), runtime_parameters(obj)
            if name == "fit":
                assert_options_spelled_out(stub, runtime, neutrospline.fit_options(), name)
            elif name == "fit_surface":
                assert_options_spelled_out(stub, runtime, neutrospline.fit_surface_options(), name)
            elif name == "inline":
                assert_options_spelled_out(stub, runtime, neutrospline.figure_options(), name)
            elif name == "load":
                options = neutrospline.import_options() + neutrospline.table_options()
                assert_options_spelled_out(stub, runtime, options, name)
            else:
                assert stub == runtime, name


def assert_options_spelled_out(stub, runtime, options, name):
    """A function that reads a job's options from `**options` (the names `fit_options()` or
    `figure_options()` list): the stub spells each out as a typed keyword."""
    assert runtime[-1] == "options", runtime
    named = runtime[:-1]
    assert stub[: len(named)] == named, name
    names = {o["name"] for o in options} - set(named)
    assert set(stub[len(named):]) == names, name


def test_every_method_is_in_the_stub():
    _, classes, _ = stub_tree()
    for class_name in [
        "Shape", "Curve", "Bezier", "BSpline", "Nurbs",
        "Surface", "BezierSurface", "BSplineSurface", "NurbsSurface",
    ]:
        cls = getattr(neutrospline, class_name)
        stub = classes[class_name]
        for name, member in vars(cls).items():
            if name.startswith("__") and name not in ("__call__", "__len__", "__eq__", "__reduce__"):
                continue
            assert name in stub, f"{class_name}.{name}"
            if isinstance(stub[name], ast.AnnAssign):
                # An alias of a class: the stub names that class.
                assert isinstance(member, type), f"{class_name}.{name}"
                assert f'"{member.__name__}"' in ast.unparse(stub[name].annotation).replace("'", '"'), (
                    f"{class_name}.{name}"
                )
                continue
            if callable(member) and not isinstance(member, (staticmethod, classmethod)):
                try:
                    runtime = runtime_parameters(member)
                except (TypeError, ValueError):
                    continue
                if runtime == ["args", "kwargs"]:
                    # A slot wrapper (__call__, __len__): CPython shows no parameter names.
                    continue
                if name in ("to_svg", "save_figure", "transform"):
                    listed = neutrospline.transform_options() if name == "transform" else neutrospline.figure_options()
                    assert_options_spelled_out(parameter_names(stub[name]), runtime, listed, f"{class_name}.{name}")
                    continue
                assert parameter_names(stub[name]) == runtime, f"{class_name}.{name}"

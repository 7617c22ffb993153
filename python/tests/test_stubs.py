"""The type stubs (frictionlab.pyi, beside the module) name what the module has, and help()
documents every function."""

import ast
import inspect
import pathlib

import frictionlab as fl


def stub_tree():
    beside = pathlib.Path(fl.__file__).with_name("frictionlab.pyi")
    assert beside.is_file(), f"no stubs beside the module at {beside}"
    return ast.parse(beside.read_text())


def names_in(body, dunders=True):
    names = set()
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            if dunders or not node.name.startswith("_"):
                names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            if dunders or not node.target.id.startswith("_"):
                names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets)
    return names


def public(obj):
    return {n for n in dir(obj) if not n.startswith("_")}


def test_module_names():
    tree = stub_tree()
    aliases = {"PathLike", "Quantity", "Overrides", "SweepColumn"}  # the stubs' own type names
    assert names_in(tree.body) - aliases == public(fl) | {"__version__"}


def classes(body, prefix=""):
    for node in body:
        if isinstance(node, ast.ClassDef):
            yield prefix + node.name, node
            yield from classes(node.body, prefix + node.name + ".")


def test_class_members():
    stubbed_classes = dict(classes(stub_tree().body))
    for qualified, node in stubbed_classes.items():
        cls = fl
        for part in qualified.split("."):
            cls = getattr(cls, part)
        if issubclass(cls, BaseException):
            continue  # its file, line and column are set on each error (test_scene.py)
        members = public(cls)
        if "__members__" in dir(cls):  # pybind11 enums: their values and name, value
            members -= {"name", "value"} | set(cls.__members__)
            stubbed = names_in(node.body, False) - {"name", "value"} - set(cls.__members__)
        else:
            stubbed = names_in(node.body, False)
            for base in node.bases:  # what a subclass inherits from its stubbed base
                if isinstance(base, ast.Name) and base.id in stubbed_classes:
                    stubbed |= names_in(stubbed_classes[base.id].body, False)
        assert stubbed == members, qualified


def test_help_documents_every_function():
    for name in public(fl):
        obj = getattr(fl, name)
        if inspect.isclass(obj):
            assert obj.__doc__, name
        elif callable(obj):
            doc = obj.__doc__
            assert doc and doc.startswith(f"{name}("), name  # the signature, then the text
            assert len(doc.splitlines()) > 2, name

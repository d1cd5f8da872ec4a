"""The type stub vibroimpact/__init__.pyi against the package, and the docstrings: the stub names
exactly the public names with the parameters and defaults inspect.signature reads from the real
objects, and each public call's numpydoc docstring describes every parameter."""

import ast
import inspect
import re

import pytest

import vibroimpact as vi
from conftest import SOURCE_DIR

STUB = SOURCE_DIR / "python/vibroimpact/__init__.pyi"


def stub_tree():
    return ast.parse(STUB.read_text())


def stub_parameters(node):
    """(name, kind, default) of a stub def, as inspect.Parameter gives them (defaults as values)."""
    a = node.args
    positional = a.posonlyargs + a.args
    defaults = [inspect.Parameter.empty] * (len(positional) - len(a.defaults)) + [ast.literal_eval(d) for d in a.defaults]
    out = [(p.arg, inspect.Parameter.POSITIONAL_OR_KEYWORD, d) for p, d in zip(positional, defaults)]
    out += [(p.arg, inspect.Parameter.KEYWORD_ONLY, inspect.Parameter.empty if d is None else ast.literal_eval(d))
            for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    return out


def real_parameters(obj):
    return [(p.name, p.kind, p.default) for p in inspect.signature(obj).parameters.values()]


def decorators(node):
    return {d.id for d in node.decorator_list if isinstance(d, ast.Name)}


def stub_names(tree):
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            names[node.target.id] = node
    return names


def test_the_stub_names_exactly_the_public_names():
    assert set(stub_names(stub_tree())) == set(vi.__all__)
    for name in vi.__all__:
        assert hasattr(vi, name), name


@pytest.mark.parametrize("name", ["load", "modes", "simulate", "pullin", "sweep", "uq", "fit", "optimize", "paper"])
def test_each_function_has_the_stubs_signature(name):
    node = stub_names(stub_tree())[name]
    assert stub_parameters(node) == real_parameters(getattr(vi, name))


def test_the_classes_have_the_stubs_methods_and_signatures():
    for cls in ("Case", "Table"):
        node = stub_names(stub_tree())[cls]
        real = getattr(vi, cls)
        stubbed = {n.name: n for n in node.body if isinstance(n, ast.FunctionDef)}
        public = {n for n in vars(real) if not n.startswith("_")} | ({"__init__"} & set(vars(real)))
        assert set(stubbed) == public, cls
        for method, n in stubbed.items():
            attribute = inspect.getattr_static(real, method)
            if "property" in decorators(n):
                assert isinstance(attribute, property), method
                continue
            assert ("classmethod" in decorators(n)) == isinstance(attribute, classmethod), method
            assert ("staticmethod" in decorators(n)) == isinstance(attribute, staticmethod), method
            expected = stub_parameters(n)
            if isinstance(attribute, classmethod):
                expected = expected[1:]  # the bound classmethod's signature leaves cls out
            actual = real_parameters(getattr(real, method) if isinstance(attribute, (classmethod, staticmethod)) else attribute)
            assert expected == actual, method


def test_input_error_has_the_stubs_attributes(small_case):
    node = stub_names(stub_tree())["InputError"]
    attributes = {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
    assert attributes == {"file", "line", "key", "option", "reason"}
    with pytest.raises(vi.InputError) as e:
        vi.Case.from_file(small_case).set("supports[0].nosuch", 1.0)
    for a in attributes:
        assert hasattr(e.value, a), a


def documented_parameters(doc):
    """Parameter names of a numpydoc "Parameters" section ("a, b : int" names two)."""
    section = re.search(r"\nParameters\n-+\n(.*?)(?:\n\n(?:Returns|Raises)\n|\Z)", doc, re.S)
    assert section, "no Parameters section"
    names = set()
    for line in section.group(1).splitlines():
        head = re.match(r"^(\w[\w, ]*?)(?: : .*)?$", line)
        if head:
            names |= {n.strip() for n in head.group(1).split(",")}
    return names


def public_calls():
    calls = [(name, getattr(vi, name)) for name in ("load", "modes", "simulate", "pullin", "sweep", "uq", "fit", "optimize",
                                                      "paper")]
    calls += [(f"Case.{m}", getattr(vi.Case, m)) for m in ("from_file", "from_string", "from_dict", "get", "set", "update",
                                                           "to_toml", "to_dict", "copy", "paths")]
    calls.append(("Table.to_pandas", vi.Table.to_pandas))
    return calls


# Calls that change the case in place and return nothing.
MUTATORS = {"Case.set", "Case.update"}


@pytest.mark.parametrize("name, call", public_calls(), ids=[n for n, _ in public_calls()])
def test_each_public_call_has_a_numpydoc_docstring_of_its_parameters(name, call):
    doc = "\n" + inspect.getdoc(call)
    assert (re.search(r"\nReturns\n-+\n", doc) is None) == (name in MUTATORS), name
    parameters = [p for p in inspect.signature(call).parameters if p not in ("self", "cls")]
    if parameters:
        assert documented_parameters(doc) == set(parameters), name

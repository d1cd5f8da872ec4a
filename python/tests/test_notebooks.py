"""The notebooks of examples/notebooks/: stored without outputs, and each runs from start to end
(nbclient with the python3 kernel of ipykernel)."""

import json
import os
import pathlib

import pytest

from conftest import SOURCE_DIR

FOLDER = SOURCE_DIR / "examples/notebooks"
NOTEBOOKS = sorted(FOLDER.glob("*.ipynb"))


def test_the_paper_and_switch_notebooks_are_there():
    assert {p.name for p in NOTEBOOKS} >= {"paper_reproduction.ipynb", "switch_design.ipynb"}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_a_notebook_is_stored_without_outputs(path):
    notebook = json.loads(path.read_text())
    for i, cell in enumerate(notebook["cells"]):
        if cell["cell_type"] == "code":
            assert cell["outputs"] == [], f"cell {i} holds outputs"
            assert cell["execution_count"] is None, f"cell {i} holds an execution count"
        assert set(cell["metadata"]) <= {"tags"}, f"cell {i} holds metadata {sorted(cell['metadata'])}"
    assert set(notebook["metadata"]) <= {"kernelspec", "language_info"}
    assert set(notebook["metadata"].get("language_info", {})) <= {"name"}, "the interpreter's version is not stored"


def notebook_tools():
    """nbformat, nbclient and a python3 kernel (ipykernel), or a skip that names the Debian packages."""
    missing = []
    for module, package in (("nbformat", "python3-nbformat"), ("nbclient", "python3-nbclient"),
                            ("ipykernel", "python3-ipykernel")):
        try:
            __import__(module)
        except ImportError:
            missing.append(package)
    if missing:
        pytest.skip(f"cannot run notebooks: {', '.join(missing)} missing (Debian: jupyter-nbconvert python3-nbclient "
                    "python3-ipykernel; bash scripts/install-deps test)")
    import nbclient
    import nbformat

    return nbformat, nbclient


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_a_notebook_runs_from_start_to_end(path, tmp_path, monkeypatch):
    nbformat, nbclient = notebook_tools()
    import vibroimpact

    # The kernel imports the module this test imports, wherever the test's path found it.
    package_parent = str(pathlib.Path(vibroimpact.__file__).resolve().parents[1])
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(filter(None, [package_parent, os.environ.get("PYTHONPATH")])))
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # ipykernel's debugger note about frozen modules
    # Run beside a link to the examples, as in the source tree, so that a file the notebook writes
    # lands in tmp_path and its relative paths (../switch/...) hold.
    (tmp_path / "notebooks").mkdir()
    for folder in ("switch", "paper", "devices"):
        (tmp_path / folder).symlink_to(SOURCE_DIR / "examples" / folder)
    notebook = nbformat.read(path, as_version=4)
    # kernel_name python3: ipykernel's own kernel, this interpreter (the one the module was built for).
    client = nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path / "notebooks")}})
    client.execute()
    errors = [o for c in notebook.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert errors == []
    assert list((tmp_path / "notebooks").iterdir()) == [], "the notebook leaves no file behind"

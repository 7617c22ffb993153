"""examples/friction-lab.ipynb is examples/friction_lab.py's cells, word for word (make_notebook.py
writes it), so that running either runs the other (tests/python: both run headless)."""

import importlib.util
import json

from conftest import SOURCE_DIR


def make_notebook():
    path = SOURCE_DIR / "examples" / "make_notebook.py"
    spec = importlib.util.spec_from_file_location("make_notebook", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_notebook_is_the_scripts_cells():
    script = (SOURCE_DIR / "examples" / "friction_lab.py").read_text()
    notebook = json.loads((SOURCE_DIR / "examples" / "friction-lab.ipynb").read_text())
    found = [(cell["cell_type"], "".join(cell["source"])) for cell in notebook["cells"]]
    assert found == make_notebook().cells(script)
    assert all(not cell.get("outputs") for cell in notebook["cells"])  # kept without outputs
    assert len(found) > 5

#!/usr/bin/env python3
"""Writes examples/friction-lab.ipynb from examples/friction_lab.py, whose "# %%" parts are the
notebook's cells ("# %% [markdown]" parts, without their "# ", its text), up to the line
"# ---- the notebook ends here ----". Edit the script, then run this:

  /usr/bin/python3 examples/make_notebook.py
"""

import pathlib

import nbformat

HERE = pathlib.Path(__file__).resolve().parent
SCRIPT = HERE / "friction_lab.py"
NOTEBOOK = HERE / "friction-lab.ipynb"
END = "# ---- the notebook ends here ----"


def cells(script_text):
    """[(kind, source)] of the script's cells, kind "code" or "markdown"."""
    body = script_text.split(END, 1)[0]
    out = []
    for part in body.split("\n# %%")[1:]:
        header, _, source = part.partition("\n")
        if header.strip() == "[markdown]":
            lines = [line[2:] if line.startswith("# ") else line.lstrip("#") for line in source.splitlines()]
            out.append(("markdown", "\n".join(lines).strip()))
        else:
            out.append(("code", source.strip()))
    return out


def notebook(script_text):
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nb.metadata["language_info"] = {"name": "python"}
    for kind, source in cells(script_text):
        make = nbformat.v4.new_markdown_cell if kind == "markdown" else nbformat.v4.new_code_cell
        nb.cells.append(make(source))
    return nb


def main():
    nb = notebook(SCRIPT.read_text())
    for i, cell in enumerate(nb.cells):  # ids stable from one writing to the next
        cell["id"] = f"cell-{i}"
    NOTEBOOK.write_text(nbformat.writes(nb) + "\n")
    print(f"wrote {NOTEBOOK} ({len(nb.cells)} cells)")


if __name__ == "__main__":
    main()

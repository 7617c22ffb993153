"""The documentation site's pages that live outside docs/ (mkdocs.yml names this file in `hooks`).

mkdocs reads pages only from docs/, but the repository's front door is README.md and the
performance figures are bench/README.md. docs/index.md and docs/performance.md are pointers to
them; when the site is built, each pointer's text is replaced by the file it points to, with the
links rewritten so that they resolve from docs/. There is one copy of each text, so the site and
the repository cannot disagree, and `mkdocs build --strict` checks every rewritten link.
"""

import os
import re

# A page of the site -> the file (from the repository's root) whose text it shows.
PAGES = {
    "index.md": "README.md",
    "performance.md": "bench/README.md",
}
# Those files, as a link in any of them names them -> the page that shows them.
SHOWN_AS = {source: page for page, source in PAGES.items()}

# A Markdown link or image target: ](target) or ](target "title"); not a URL, not an anchor.
LINK = re.compile(r"\]\((?!https?:|mailto:|#)([^)\s]+)([^)]*)\)")


def _rewrite(markdown: str, source: str) -> str:
    """The links of `source` (relative to its own folder) made relative to docs/."""
    folder = os.path.dirname(source)

    def target(match: re.Match) -> str:
        path, anchor = match.group(1), ""
        if "#" in path:
            path, anchor = path.split("#", 1)
            anchor = "#" + anchor
        resolved = os.path.normpath(os.path.join(folder, path))
        if resolved in SHOWN_AS:
            resolved = SHOWN_AS[resolved]
        elif resolved.startswith("docs/"):
            resolved = resolved[len("docs/"):]
        else:
            # Outside docs/: left as it is, so that the strict build names it.
            resolved = os.path.relpath(resolved, "docs")
        return "](" + resolved + anchor + match.group(2) + ")"

    return LINK.sub(target, markdown)


def on_page_markdown(markdown, page, config, files, **kwargs):
    source = PAGES.get(page.file.src_path.replace(os.sep, "/"))
    if source is None:
        return markdown
    root = os.path.dirname(config["config_file_path"])
    with open(os.path.join(root, source), encoding="utf-8") as f:
        return _rewrite(f.read(), source)

#!/usr/bin/env python3
"""Writes the static site's service worker, DIR/sw.js, from web/site_worker.js: the list of every
file in DIR (and "./", the folder's own address) and their digest (SHA-256 of the names and
contents, 16 hex digits), which names the cache. tools/site runs it on the folder it builds.
  tools/site_worker.py DIR"""

import hashlib
import json
import pathlib
import sys

if len(sys.argv) != 2:
    sys.exit("usage: tools/site_worker.py DIR (the site's folder)")
site = pathlib.Path(sys.argv[1])
if not site.is_dir():
    sys.exit(f"tools/site_worker.py: {site} is not a folder: build the site first (tools/site)")
template = pathlib.Path(__file__).resolve().parents[1] / "web" / "site_worker.js"

files = sorted(p.relative_to(site).as_posix() for p in site.rglob("*") if p.is_file() and p.name != "sw.js")
digest = hashlib.sha256()
for name in files:
    digest.update(name.encode() + b"\0" + (site / name).read_bytes())
text = template.read_text()
for placeholder in ("SITE_DIGEST", "SITE_FILES"):
    if placeholder not in text:
        sys.exit(f"tools/site_worker.py: {template} has no {placeholder} to fill in")
text = text.replace("SITE_DIGEST", json.dumps(digest.hexdigest()[:16]))
text = text.replace("SITE_FILES", json.dumps(["./"] + files))
tmp = site / "sw.js.tmp"
tmp.write_text(text)
tmp.replace(site / "sw.js")
print(f"tools/site_worker.py: {len(files)} files, version {digest.hexdigest()[:16]}")

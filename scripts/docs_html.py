#!/usr/bin/env python3
"""Writes the guides of docs/*.md into OUT as HTML pages the app links to, plus an index.

The Markdown is shown as written (escaped, in a wrapping <pre>), so no renderer is needed, less
its HTML comments (the rows a measured number shows, see scripts/measured-docs.mjs), which a
Markdown renderer would not show either; the .md files are copied beside them. Usage: scripts/docs_html.py OUT
"""
import html
import re
import pathlib
import shutil
import sys

PAGE = """<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title} · IM Lab</title>
<style>body {{ margin: 0 auto; max-width: 50rem; padding: 1rem; font: 1rem/1.5 system-ui, sans-serif; color: #111; }}
pre {{ white-space: pre-wrap; overflow-wrap: anywhere; font: 0.95rem/1.5 ui-monospace, monospace; }}
a {{ color: #1f5fa8; }}</style>
</head>
<body>
<nav aria-label="Guides"><a href="../">Back to IM Lab</a> · <a href="./">All guides</a> · <a href="{name}.md">Markdown source</a></nav>
<main>
<h1>{title}</h1>
<pre>{body}</pre>
</main>
</body>
</html>
"""


def main() -> None:
    root = pathlib.Path(__file__).resolve().parent.parent
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    items = []
    for md in sorted((root / "docs").glob("*.md")):
        text = md.read_text(encoding="utf-8")
        text = re.sub(r"<!--[^\n]*?-->", "", text)
        text = re.sub(r"<!--.*?-->\n?", "", text, flags=re.S)
        lines = text.splitlines()
        title = lines[0].lstrip("# ").strip() if lines else md.stem
        body = "\n".join(lines[1:]).strip("\n")
        page = PAGE.format(title=html.escape(title), name=md.stem, body=html.escape(body))
        (out / f"{md.stem}.html").write_text(page, encoding="utf-8")
        shutil.copyfile(md, out / md.name)
        items.append(f'<li><a href="{md.stem}.html">{html.escape(title)}</a></li>')
    index = PAGE.replace(' · <a href="{name}.md">Markdown source</a>', "")
    index = index.replace("<pre>{body}</pre>", "<ul>\n{body}\n</ul>")
    body = "\n".join(items)
    (out / "index.html").write_text(index.format(title="IM Lab guides", name="", body=body), encoding="utf-8")


if __name__ == "__main__":
    main()

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
<html lang="{lang}">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title} · IM Lab</title>
<style>body {{ margin: 0 auto; max-width: 50rem; padding: 1rem; font: 1rem/1.5 system-ui, sans-serif; color: #111; }}
pre {{ white-space: pre-wrap; overflow-wrap: anywhere; font: 0.95rem/1.5 ui-monospace, monospace; }}
a {{ color: #1f5fa8; }}</style>
</head>
<body>
<nav aria-label="Guides"><a href="{up}../">Back to IM Lab</a> · <a href="{up}./">All guides</a> · <a href="{name}.md">Markdown source</a></nav>
<main>
<h1>{title}</h1>
<pre>{body}</pre>
</main>
</body>
</html>
"""

# The languages of the translated guides, by the name of their folder in docs/.
LANGUAGES = {"de": "Deutsch", "es": "Español", "fr": "Français", "zh-CN": "简体中文", "ja": "日本語"}


def main() -> None:
    root = pathlib.Path(__file__).resolve().parent.parent
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    items = []
    # The guides in English, then their translations (docs/LANG/*.md, in docs/LANG/ beside them).
    guides = [(md, "en") for md in sorted((root / "docs").glob("*.md"))]
    guides += [(md, md.parent.name) for md in sorted((root / "docs").glob("*/*.md")) if md.parent.name in LANGUAGES]
    for md, lang in guides:
        text = md.read_text(encoding="utf-8")
        text = re.sub(r"<!--[^\n]*?-->", "", text)
        text = re.sub(r"<!--.*?-->\n?", "", text, flags=re.S)
        lines = text.splitlines()
        title = lines[0].lstrip("# ").strip() if lines else md.stem
        body = "\n".join(lines[1:]).strip("\n")
        where = out if lang == "en" else out / lang
        where.mkdir(parents=True, exist_ok=True)
        up = "" if lang == "en" else "../"
        page = PAGE.format(title=html.escape(title), name=md.stem, body=html.escape(body), lang=lang, up=up)
        (where / f"{md.stem}.html").write_text(page, encoding="utf-8")
        shutil.copyfile(md, where / md.name)
        suffix = "" if lang == "en" else f" ({LANGUAGES[lang]})"
        items.append(f'<li><a href="{up and lang + "/"}{md.stem}.html" lang="{lang}">{html.escape(title)}{suffix}</a></li>')
    index = PAGE.replace(' · <a href="{name}.md">Markdown source</a>', "")
    index = index.replace("<pre>{body}</pre>", "<ul>\n{body}\n</ul>")
    body = "\n".join(items)
    page = index.format(title="IM Lab guides", name="", body=body, lang="en", up="")
    (out / "index.html").write_text(page, encoding="utf-8")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The documentation's links hold, and docs/json.md names every folder of a report's data.

Read: README.md, every docs/*.md and the Markdown cells of reports/data/explore.ipynb (fenced code
blocks and inline code left out). Checked:

- every relative Markdown link or image, [text](path) or [text](path#anchor), names a file or
  folder that exists (relative to the file it is in), and an anchor names a heading of that file;
  a bare [text](#anchor) a heading of the same file. Anchors are GitHub's: the heading's text
  lower-cased, every character but letters, digits, '_', '-' and spaces dropped, spaces turned to
  hyphens, a repeated heading suffixed -1, -2, ... Links with a scheme (https:, mailto:) are not
  followed.
- every section named in prose, 'the "X" section of docs/Y.md' or 'docs/Y.md, "X"' (README as
  well as a file name), is a heading of that file.
- docs/json.md's "report's data" part (the section holding the `| folder |` table) names each
  folder a report writes under data/: reports/document/write_report.cpp writes each section's data
  into data/<its id>/, the ids are the X(<id>, ...) list of reports/document/sections/sections.hpp,
  and a section writes data if the file defining make_<id>_section() overrides write_data. A
  folder the table names that no section writes fails too.

One line per broken link or name (file:line, the link, why); exit status 1 if any, else 0.
Python 3's standard library only.

Usage: docs_links_test.py SOURCE_DIR
"""
import glob
import json
import os
import re
import sys
import urllib.parse

src = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
problems = []


def rel(path):
    return os.path.relpath(path, src)


def report(where, link, why):
    problems.append(f"{where}: {link}: {why}")


# --- reading Markdown ------------------------------------------------------------------------

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")


def without_fences(text):
    """The text with every fenced code block's lines blanked (line numbers kept)."""
    out, fence = [], None
    for line in text.split("\n"):
        m = FENCE.match(line)
        if fence is None and m:
            fence = m.group(1)[0] * len(m.group(1))
            out.append("")
        elif fence is not None:
            if m and m.group(1).startswith(fence) and line.strip().strip(fence[0]) == "":
                fence = None
            out.append("")
        else:
            out.append(line)
    return "\n".join(out)


INLINE_CODE = re.compile(r"(`+)(.+?)(?<!`)\1(?!`)", re.S)


def without_code(text):
    """No fenced blocks and every inline code span blanked (same length, so offsets hold)."""
    return INLINE_CODE.sub(lambda m: " " * len(m.group(0)), without_fences(text))


def heading_text(raw):
    """A heading's text as rendered: links to their text, code and emphasis marks gone."""
    t = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", raw)
    t = re.sub(r"<[^>]+>", "", t)
    return t.replace("`", "").replace("*", "").strip()


def slug(text):
    s = heading_text(text).lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def headings(text):
    """Each heading's rendered text, in order (ATX and setext; none inside code blocks)."""
    lines = without_fences(text).split("\n")
    out = []
    for i, line in enumerate(lines):
        m = re.match(r"^ {0,3}#{1,6}(?:\s+(.*?))?\s*$", line)
        if m:
            out.append(re.sub(r"\s+#+\s*$", "", m.group(1) or "").strip())
            continue
        if (i > 0 and re.match(r"^ {0,3}(=+|-+)\s*$", line) and lines[i - 1].strip()
                and "|" not in lines[i - 1] and not re.match(r"^\s*([-*+]|\d+\.)\s", lines[i - 1])
                and not re.match(r"^ {0,3}#", lines[i - 1])):
            out.append(lines[i - 1].strip())
    return out


def anchors(text):
    """GitHub's anchors of a file: each heading's slug (repeats suffixed -1, -2, ...) and HTML ids."""
    seen, out = {}, set()
    for h in headings(text):
        s = slug(h)
        n = seen.get(s, 0)
        seen[s] = n + 1
        out.add(s if n == 0 else f"{s}-{n}")
    out.update(re.findall(r"<a\s+(?:name|id)=\"([^\"]+)\"", text))
    return out


_cache = {}


def read(path):
    if path not in _cache:
        if path.endswith(".ipynb"):
            _cache[path] = notebook_markdown(path)
        else:
            with open(path, encoding="utf-8") as f:
                _cache[path] = f.read()
    return _cache[path]


def notebook_markdown(path):
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    cells = [c for c in nb.get("cells", []) if c.get("cell_type") == "markdown"]
    return "\n\n".join("".join(c["source"]) if isinstance(c["source"], list) else c["source"] for c in cells)


# --- the links -------------------------------------------------------------------------------

LINK = re.compile(r"(!?)\[((?:[^\[\]]|\[[^\]]*\])*)\]\(\s*<?([^)\s>]*)>?(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def check_links(path, text):
    base = os.path.dirname(path)
    body = without_code(text)
    for m in LINK.finditer(body):
        target = m.group(3)
        where = f"{rel(path)}:{line_of(body, m.start())}"
        if not target:
            report(where, m.group(0), "empty link")
            continue
        if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target) or target.startswith("//"):
            continue  # a URL: not followed
        file_part, _, anchor = target.partition("#")
        file_part = urllib.parse.unquote(file_part)
        anchor = urllib.parse.unquote(anchor)
        dest = path if not file_part else os.path.normpath(os.path.join(base, file_part))
        if file_part and not os.path.exists(dest):
            report(where, target, f"no file {rel(dest)}")
            continue
        if not anchor and "#" not in target:
            continue
        if os.path.isdir(dest):
            report(where, target, f"an anchor on a folder ({rel(dest)})")
        elif dest.endswith((".md", ".ipynb")):
            if anchor not in anchors(read(dest)):
                report(where, target, f"no heading with anchor #{anchor} in {rel(dest)}")
        elif not re.fullmatch(r"L\d+(-L\d+)?", anchor):
            report(where, target, f"an anchor #{anchor} on {rel(dest)}, which is not Markdown")


# --- sections named in prose -----------------------------------------------------------------

FILE = r"`?((?:[\w.-]+/)*[\w.-]+\.md|README)`?"
QUOTED = r"[\"\u201c]([^\"\u201d\n]+)[\"\u201d]"
NAMED = [re.compile(r"\bthe\s+" + QUOTED + r"\s+section\s+(?:of|in)\s+" + FILE),
         re.compile(r"(?<![\w./-])" + FILE + r",\s*" + QUOTED)]


def resolve_doc(name, path):
    if name == "README":
        name = "README.md"
    for cand in (os.path.join(src, name), os.path.join(os.path.dirname(path), name)):
        if os.path.isfile(cand):
            return os.path.normpath(cand)
    return None


def check_named_sections(path, text):
    prose = without_fences(text)
    flat = re.sub(r"\s*\n\s*", " ", prose)  # a name may break across lines
    for pattern in NAMED:
        for m in pattern.finditer(flat):
            section, name = (m.group(1), m.group(2)) if pattern is NAMED[0] else (m.group(2), m.group(1))
            k = prose.find(section)  # its line: the quoted name's first place in the text
            where = f"{rel(path)}:{line_of(prose, k) if k >= 0 else '?'}"
            doc = resolve_doc(name, path)
            named = f'{name}, "{section}"'
            if doc is None:
                report(where, named, f"no file {name}")
                continue
            titles = {heading_text(h).lower() for h in headings(read(doc))}
            if heading_text(section).lower() not in titles and slug(section) not in anchors(read(doc)):
                report(where, named, f"no section \"{section}\" in {rel(doc)}")


# --- the report's data folders ---------------------------------------------------------------

def source(relpath):
    with open(os.path.join(src, relpath), encoding="utf-8") as f:
        return f.read()


def written_folders():
    """The folders a report writes under data/, from the source; None (and a problem) if the
    source no longer builds them as this test reads it."""
    report_cpp = source("reports/document/write_report.cpp")
    if not re.search(r"\"data\"\s*/\s*\w+->id\b", report_cpp):
        report("reports/document/write_report.cpp", "data/<section id>/",
               "no longer found (`\"data\" / s->id`): teach tests/docs_links_test.py how the report names its data folders")
        return None
    ids = re.findall(r"\bX\((\w+),\s*(?:true|false),\s*\w+\)", source("reports/document/sections/sections.hpp"))
    if not ids:
        report("reports/document/sections/sections.hpp", "X(<id>, ...)", "no section list found")
        return None
    files = glob.glob(os.path.join(src, "reports/document/sections/*.cpp"))
    out = set()
    for i in ids:
        defining = [f for f in files if re.search(rf"\bmake_{i}_section\s*\(\s*\)\s*\{{", source(f))]
        if not defining:
            report("reports/document/sections", f"make_{i}_section()", "defined in no file")
            continue
        if any(re.search(r"\bvoid\s+write_data\s*\([^)]*\)\s*const\s+override\b", source(f)) for f in defining):
            out.add(i)
    return out


def check_data_folders():
    written = written_folders()
    if written is None:
        return
    path = os.path.join(src, "docs/json.md")
    text = read(path)
    lines = text.split("\n")
    table = next((k for k, line in enumerate(lines) if re.match(r"^\|\s*folder\s*\|", line)), None)
    if table is None:
        report("docs/json.md", "| folder | ...", "no table of the report's data folders")
        return
    start = max((k for k in range(table) if lines[k].startswith("#")), default=0)
    end = next((k for k in range(table, len(lines)) if lines[k].startswith("#")), len(lines))
    part = "\n".join(lines[start:end])
    named = set(re.findall(r"`(\w+)/`", part))
    for folder in sorted(written - named):
        report(f"docs/json.md:{start + 1}", f"data/{folder}/",
               "a folder the report writes (reports/document/sections) that docs/json.md does not name")
    for k in range(table + 2, end):
        m = re.match(r"^\|\s*`(\w+)/`\s*\|", lines[k])
        if m:
            if m.group(1) not in written:
                report(f"docs/json.md:{k + 1}", f"data/{m.group(1)}/", "named in the table but written by no section")


# --- run -------------------------------------------------------------------------------------

documents = [os.path.join(src, "README.md")] + sorted(glob.glob(os.path.join(src, "docs", "*.md")))
documents.append(os.path.join(src, "reports", "data", "explore.ipynb"))
for doc in documents:
    if not os.path.isfile(doc):
        report(rel(doc), "-", "missing")
        continue
    text = read(doc)
    check_links(doc, text)
    check_named_sections(doc, text)
check_data_folders()

for p in problems:
    print(p)
if problems:
    print(f"{len(problems)} broken")
    sys.exit(1)
print(f"docs links: {len(documents)} files checked, every link, named section and report data folder holds")

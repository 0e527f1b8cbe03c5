#!/usr/bin/env python3
"""Holds a report's figures to the written figure rules (docs/design.md, "Figures a student can
read"), reading what gnuplot drew, the SVG of each figure, and the captions of atlas.md; it shares
no code with the report.

    figure_rules_check.py REPORT_DIR

For each figures/fig<n>_<name>.svg, by panel (a `plot` of a multiplot: gnuplot names its curves
gnuplot_plot_<k><panel letter>):
  - at most 6 panels a figure and 6 curves (curves with a key entry) a panel;
  - two curves of a panel differ in colour, and in dash or marker (as their key samples draw them);
  - at most 6 labelled ticks an axis, and on an axis labelled in powers of ten only whole decades;
  - no text under 8 pt in print (9.6 px on the 1100 px wide screen figure, whose 12 px is 10 pt).
For each figure of report.md and atlas.md: the caption ends with a sentence that carries a number
or a method (`name`), the one computed sentence of what to see.
Prints one line per broken rule and exits 1 if there is any.
"""
import pathlib
import re
import sys
from collections import defaultdict

# text: 12 px on the screen figure is 10 pt in print (styles.gp's terminal()), so 9.6 px (an
# exponent of the axis font, 0.8 of it) is the least, 8 pt
MAX_PANELS, MAX_CURVES, MAX_TICKS, MIN_FONT = 6, 6, 6, 9.6

GROUP = re.compile(r'<g id="gnuplot_plot_(\d+)([a-z]*)" ><title>(.*?)</title>')
TICK = re.compile(r"<path stroke='black'\s+d='M[^']*'/>\s*<g transform=\"translate\(([-\d.]+),([-\d.]+)\)\"[^>]*"
                  r'text-anchor="(end|middle|start)">\s*<text>(.*?)</text>', re.S)
RGB = re.compile(r"(?:color|stroke)='rgb\(\s*(\d+),\s*(\d+),\s*(\d+)\)'")
POINT = re.compile(r"xlink:href='#gpPt(\d+)'")
DASH = re.compile(r"stroke-dasharray='([^']*)'")
PATH = re.compile(r"<path stroke='rgb")
FONT = re.compile(r'font-size="([\d.]+)"')


def text_of(svg_text):
    """The characters of a <text> element, its tspans joined."""
    return re.sub(r"<[^>]+>", "", svg_text).strip()


def curve_style(body):
    """(colour, dash or None, marker or None) of a curve as its first drawing (the key sample) draws it."""
    colour = RGB.search(body)
    colour = tuple(int(c) for c in colour.groups()) if colour else None
    point = POINT.search(body)
    dash = None
    if PATH.search(body):
        d = DASH.search(body)
        dash = d.group(1) if d else "solid"
    return colour, dash, point.group(1) if point else None


def distinguishable(a, b):
    """Apart in colour, and in dash or marker (a line against a line with points counts: the
    marker is there or not)."""
    (ca, da, pa), (cb, db, pb) = a, b
    return ca != cb and (da, pa) != (db, pb)


def decades_only(labels):
    """On an axis labelled 10^k (gnuplot's enhanced text draws 10 and a superscript), every label
    is a whole power of ten."""
    powers = [l for l in labels if re.fullmatch(r"10\s*-?\d+", l)]
    if not powers or len(powers) < len(labels) - 1:
        return True  # not a log axis labelled in powers of ten
    return all(re.fullmatch(r"(10\s*-?\d+|1|0\.1|10)", l) for l in labels)


def check_svg(path, problems):
    svg = path.read_text()
    fig = path.stem
    # a curve: (title, its drawing up to the next curve's, where it starts); a curve with a key
    # entry draws its title as text
    found = list(GROUP.finditer(svg))
    panels = defaultdict(list)
    order = []
    ends = {}
    for i, g in enumerate(found):
        end = found[i + 1].start() if i + 1 < len(found) else len(svg)
        panel = g.group(2)
        if panel not in panels:
            order.append(panel)
        panels[panel].append((g.group(3), svg[g.end():end], g.start()))
        ends[panel] = end
    # each labelled tick: (the panel of the next curve, its axis, its label)
    starts = [(g.start(), g.group(2)) for g in found]
    ticks = []
    for t in TICK.finditer(svg):
        after = [p for pos, p in starts if pos > t.start()]
        label = text_of(t.group(4))
        if after and label:
            x, y, anchor = float(t.group(1)), float(t.group(2)), t.group(3)
            ticks.append((after[0], (anchor, round(y) if anchor == "middle" else round(x)), label))
    if len(order) > MAX_PANELS:
        problems.append(f"{fig}: {len(order)} panels (at most {MAX_PANELS})")
    for panel in order:
        keyed = [(title, curve_style(body)) for title, body, _ in panels[panel]
                 if any(text_of(t) == title for t in re.findall(r"<text>.*?</text>", body, re.S))]
        where = f"{fig} panel {order.index(panel) + 1}"
        if len(keyed) > MAX_CURVES:
            problems.append(f"{where}: {len(keyed)} curves (at most {MAX_CURVES}): " + ", ".join(k for k, _ in keyed))
        for i in range(len(keyed)):
            for j in range(i):
                if not distinguishable(keyed[i][1], keyed[j][1]):
                    problems.append(f"{where}: {keyed[j][0]} and {keyed[i][0]} drawn alike {keyed[j][1]} {keyed[i][1]}")
        # a panel's ticks are drawn before its curves, after the previous panel's
        axes = defaultdict(list)
        for t in ticks:
            if t[0] == panel:
                axes[t[1]].append(t[2])
        for (anchor, _), labels in axes.items():
            axis = "x" if anchor == "middle" else "y"
            if len(labels) > MAX_TICKS:
                problems.append(f"{where}: {len(labels)} labelled {axis} ticks (at most {MAX_TICKS}): {labels}")
            if not decades_only(labels):
                problems.append(f"{where}: {axis} axis in powers of ten labels more than decades: {labels}")
    for size in FONT.findall(svg):
        if float(size) < MIN_FONT:
            problems.append(f"{fig}: text of {size} px (at least {MIN_FONT})")
            break


def check_captions(markdown, problems):
    for m in re.finditer(r"^!\[(Figure \d+): (.*)\]\((figures/[^)]*)\)", markdown, re.M):
        caption = m.group(2)
        sentences = [s for s in re.split(r"(?<=[.;])\s+(?=[A-Z`0-9])", caption) if s]
        last = sentences[-1] if len(sentences) > 1 else ""
        if not re.search(r"\d|`[a-z0-9_]+`", last):
            problems.append(f"{m.group(1)} ({m.group(3)}): the caption does not end with a computed sentence of what to see")


def main():
    if len(sys.argv) != 2:
        print("usage: figure_rules_check.py REPORT_DIR", file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1])
    problems = []
    svgs = sorted((root / "figures").glob("fig*.svg"))
    if not svgs:
        problems.append(f"{root}/figures: no SVG figure")
    for svg in svgs:
        check_svg(svg, problems)
    for md in ("report.md", "atlas.md"):
        if (root / md).exists():
            check_captions((root / md).read_text(), problems)
    for p in problems:
        print(p)
    print(f"figure rules: {len(svgs)} figures, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

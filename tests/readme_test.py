#!/usr/bin/env python3
"""The README's examples run as shown.

Every fenced block that starts with `$ build/steplab ...` is run (build/ replaced by the build
folder), and each line printed under it in the README, but for a `...` line that stands for lines
left out, must appear in the command's output in that order and exactly. Every other command the
README shows is listed with the test that runs it instead, or why none does; a command this test
does not know fails it, so a new example is either runnable here or named below.

Usage: readme_test.py BUILD_DIR SOURCE_DIR
"""
import re
import shlex
import subprocess
import sys

build, src = sys.argv[1], sys.argv[2]
readme = open(f"{src}/README.md", encoding="utf-8").read()
blocks = re.findall(r"^ *```[a-z]*\n(.*?)^ *```", readme, flags=re.S | re.M)

# Commands shown but run elsewhere, by their first words.
ELSEWHERE = {
    "make report": "CI's clean clone (.ci/run) and the report tests (ReportFindings, ReportInterrupted)",
    "make test": "CI (.ci/run)",
    "jupyter nbconvert": "notebook.explore (tests/notebook_test.sh), from a folder laid out as steplab's",
    "build/steplab report": "the report tests (a whole report takes 40 s; ReportFindings, ReportInterrupted)",
    "build/mysteplab": "readme.walkthrough (tests/readme_walkthrough_test.py), which builds mysteplab from an empty folder",
    "cmake": "readme.walkthrough and package.consumer (tests/readme_walkthrough_test.py, tests/consumer_test.sh)",
    "find_package": "package.consumer", "target_link_libraries": "package.consumer",
    "steplab_add_executable": "readme.walkthrough", "cmake_minimum_required": "readme.walkthrough",
    "project": "readme.walkthrough",
}

failures, ran, elsewhere = [], 0, []
for block in blocks:
    lines = block.rstrip("\n").split("\n")
    first = lines[0].strip()
    if first.startswith("$ ") and not first.startswith("$ build/steplab"):
        key = max((k for k in ELSEWHERE if first[2:].startswith(k)), key=len, default=None)
        if key is None:
            failures.append(f"an example the README shows that no test runs: {first}")
        else:
            elsewhere.append(f"  {first[2:]}  ->  {ELSEWHERE[key]}")
        continue
    if first.startswith("$ build/steplab"):
        cmd = first[2:].replace("build/", f"{build}/", 1)
        out = subprocess.run(shlex.split(cmd), capture_output=True, text=True, timeout=300)
        ran += 1
        if out.returncode != 0:
            failures.append(f"{first}: exit status {out.returncode}: {out.stderr.strip()}")
            continue
        got = out.stdout.split("\n")
        at = 0
        for want in lines[1:]:
            if want.strip() == "...":
                continue
            while at < len(got) and got[at] != want:
                at += 1
            if at == len(got):
                failures.append(f"{first}: the README shows a line the command does not print (in this order):\n  {want}")
                break
            at += 1
        continue
    for line in lines:
        text = line.strip()
        if not text or text.startswith(("#", "//", "$", "t,", "0,")) or not re.match(r"[a-z_]", text):
            continue
        if text.startswith(("make ", "build/", "cmake", "find_package", "target_link", "steplab_add", "project(", "jupyter")):
            key = max((k for k in ELSEWHERE if text.startswith(k)), key=len, default=None)
            if key is None:
                failures.append(f"a command the README shows that no test runs: {text}")
            else:
                elsewhere.append(f"  {text.split('#')[0].strip()}  ->  {ELSEWHERE[key]}")

print(f"README: ran {ran} examples; not run here:")
print("\n".join(sorted(set(elsewhere))))
if failures:
    print("\n".join(failures))
    sys.exit(1)

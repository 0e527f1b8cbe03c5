#!/usr/bin/env python3
"""The README's walk-through "Check your own integrator", exactly as printed, from an empty folder.

Its fenced blocks, in order: a `cpp` block is written to the file the text before it names
(Write `heun.hpp`), a `cmake` block to CMakeLists.txt, an `sh` block is run line by line, and a
block starting with `$ build/...` is run and every line the README prints under it (but `...`)
must appear in its output, in that order. Two substitutions only: the install prefix /opt/steplab
is a temporary folder, and `cmake --install build` installs steplab's build folder under test.
The build type is not named, as in the README: the tool must come out optimised anyway.

Usage: readme_walkthrough_test.py BUILD_DIR SOURCE_DIR
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile
import textwrap

build, src = (os.path.abspath(a) for a in sys.argv[1:3])
readme = open(f"{src}/README.md", encoding="utf-8").read()
start = readme.index("## Check your own integrator")
section = readme[start:readme.index("\n## ", start + 1)]

failures = []
with tempfile.TemporaryDirectory() as tmp:
    prefix, work = f"{tmp}/prefix", f"{tmp}/mine"
    os.makedirs(work)
    pos = 0
    for m in re.finditer(r"^( *)```([a-z]*)\n(.*?)^ *```", section, flags=re.S | re.M):
        lang, body = m.group(2), textwrap.dedent(m.group(3))
        before = section[pos:m.start()]
        pos = m.end()
        if lang == "cpp":
            name = re.findall(r"`([\w.]+\.hpp)`", before)[-1]
            open(f"{work}/{name}", "w").write(body)
        elif lang == "cmake":
            open(f"{work}/CMakeLists.txt", "w").write(body)
        elif lang == "sh":
            for line in body.splitlines():
                cmd = line.split("#")[0].strip().replace("/opt/steplab", prefix)
                if not cmd:
                    continue
                cwd = work
                if cmd.startswith("cmake --install build"):
                    cmd, cwd = cmd.replace("cmake --install build", f"cmake --install {shlex.quote(build)}", 1), src
                print(f"$ {line.strip()}", flush=True)
                r = subprocess.run(cmd, shell=True, cwd=cwd, capture_output=True, text=True, timeout=900)
                if r.returncode != 0:
                    failures.append(f"{line.strip()}: exit status {r.returncode}\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
                    break
        elif body.startswith("$ build/"):
            lines = body.rstrip("\n").split("\n")
            print(lines[0], flush=True)
            r = subprocess.run(shlex.split(lines[0][2:]), cwd=work, capture_output=True, text=True, timeout=900)
            if r.returncode != 0:
                failures.append(f"{lines[0]}: exit status {r.returncode}: {r.stderr.strip()}")
                continue
            got, at = r.stdout.split("\n"), 0
            for want in lines[1:]:
                if want.strip() == "...":
                    continue
                while at < len(got) and got[at] != want:
                    at += 1
                if at == len(got):
                    failures.append(f"{lines[0]}: the README shows a line it does not print (in this order):\n  {want}")
                    break
                at += 1
        if failures:
            break
    if not failures:
        # Built as the README builds it (no build type named): optimised all the same.
        flags = open(f"{work}/build/CMakeFiles/mysteplab.dir/flags.make").read()
        if "-O3" not in flags:
            failures.append("mysteplab was compiled without -O3:\n" + flags)
        if not os.path.exists(f"{work}/report/report.pdf"):
            failures.append("the walk-through's report has no report.pdf")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("README walk-through: every command as printed")

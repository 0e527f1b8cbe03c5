#!/usr/bin/env python3
"""A report's atlas in a real browser: python3 tests/atlas_browser_check.py REPORT_DIR SCREENSHOT

Loads REPORT_DIR/atlas.html from the disk in Debian's headless Chromium (chromium-headless-shell,
installed by tools/install-deps test) and checks what a reader would meet: every image loads
(complete, with a width), no script error, no console error and no resource that fails to load,
every link inside the page names an element that exists, every link to a file names one in the
folder, and no address outside it (the atlas opens offline). Writes a screenshot of the top at
1280 px wide to SCREENSHOT for a person to look at. Prints one line per problem and a summary;
exit 0 when there is none, 1 when there is, 2 when the browser or the file is missing.

The checks run in the page: a copy of atlas.html beside it (so that its relative figure paths
resolve) with two scripts added, one first in <head> that records errors, one that reports on
the window's load event into a <pre> element, read back from the browser's --dump-dom output.
"""
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from urllib.parse import unquote, urlparse

BROWSERS = ("chromium-headless-shell", "/usr/lib/chromium/chromium-headless-shell", "chromium")
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--allow-file-access-from-files",
         "--no-first-run", "--hide-scrollbars", "--disable-extensions"]

RECORD_ERRORS = """<script>
window.__atlasErrors = [];
window.addEventListener('error', function (e) {
  var t = e.target;
  window.__atlasErrors.push(t && t !== window ? 'failed to load: ' + (t.src || t.href || t.tagName)
                                              : 'script error: ' + e.message);
}, true);
(function () {
  var err = console.error;
  console.error = function () {
    window.__atlasErrors.push('console error: ' + Array.prototype.join.call(arguments, ' '));
    return err.apply(console, arguments);
  };
})();
</script>
"""

REPORT_ON_LOAD = """<script>
window.addEventListener('load', function () {
  var images = Array.prototype.slice.call(document.images);
  var bad = images.filter(function (i) { return !i.complete || i.naturalWidth === 0; })
                  .map(function (i) { return i.getAttribute('src'); });
  var anchors = Array.prototype.slice.call(document.querySelectorAll('a[href^="#"]'));
  var dead = anchors.filter(function (a) {
    var id = decodeURIComponent(a.getAttribute('href').slice(1));
    return id !== '' && !document.getElementById(id);
  }).map(function (a) { return a.getAttribute('href'); });
  var out = document.createElement('pre');
  out.id = 'atlas-check';
  out.textContent = JSON.stringify({images: images.length, bad_images: bad, internal_links: anchors.length,
                                    dead_links: dead, errors: window.__atlasErrors,
                                    sections: document.querySelectorAll('h2').length});
  document.body.appendChild(out);
});
</script>
"""


def browser():
    for b in BROWSERS:
        found = shutil.which(b)
        if found:
            return found
    return None


def file_links(page, folder):
    """Problems with the page's links and sources that are not inside the page: each must name a
    file in the folder; none may name a network address."""
    problems = []
    for attr, target in re.findall(r'\b(href|src)="([^"]*)"', page):
        target = html.unescape(target)
        if target.startswith("#") or target.startswith("data:"):
            continue
        url = urlparse(target)
        if url.scheme or url.netloc:
            problems.append("%s names an address outside the folder: %s" % (attr, target))
            continue
        path = os.path.normpath(os.path.join(folder, unquote(url.path)))
        if not path.startswith(os.path.abspath(folder) + os.sep) or not os.path.isfile(path):
            problems.append("%s names no file in the folder: %s" % (attr, target))
    return problems


def main(argv):
    if len(argv) != 3:
        print("usage: atlas_browser_check.py REPORT_DIR SCREENSHOT", file=sys.stderr)
        return 2
    folder, shot = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    atlas = os.path.join(folder, "atlas.html")
    chromium = browser()
    if not os.path.isfile(atlas) or chromium is None:
        print("atlas_browser_check: %s" % ("no %s" % atlas if chromium else
              "no headless Chromium (run: tools/install-deps test)"), file=sys.stderr)
        return 2
    with open(atlas, encoding="utf-8") as f:
        page = f.read()
    problems = file_links(page, folder)
    if "<head>" not in page or "</body>" not in page:
        print("atlas_browser_check: %s is not a whole HTML page" % atlas, file=sys.stderr)
        return 2
    checked = page.replace("<head>", "<head>\n" + RECORD_ERRORS, 1).replace("</body>", REPORT_ON_LOAD + "</body>", 1)
    t0 = time.monotonic()
    with tempfile.NamedTemporaryFile("w", suffix=".html", dir=folder, prefix=".atlas-check-",
                                     encoding="utf-8", delete=False) as f:
        f.write(checked)
        copy = f.name
    try:
        run = subprocess.run([chromium] + FLAGS + ["--virtual-time-budget=20000", "--dump-dom",
                                                   "file://" + copy],
                             capture_output=True, text=True, timeout=240)
    finally:
        os.remove(copy)
    found = re.search(r'<pre id="atlas-check">(.*?)</pre>', run.stdout, re.S)
    if not found:
        print("the page never reported on its load (the browser exited %d): %s"
              % (run.returncode, run.stderr.strip()[-400:]))
        return 1
    report = json.loads(html.unescape(found.group(1)))
    problems += ["an image does not load: %s" % s for s in report["bad_images"]]
    problems += ["a link names no element of the page: %s" % s for s in report["dead_links"]]
    problems += report["errors"]
    if report["images"] == 0:
        problems.append("the page has no image")
    os.makedirs(os.path.dirname(shot), exist_ok=True)
    subprocess.run([chromium] + FLAGS + ["--window-size=1280,2400", "--virtual-time-budget=20000",
                                         "--screenshot=" + shot, "file://" + atlas],
                   capture_output=True, text=True, timeout=240)
    if not os.path.isfile(shot):
        problems.append("no screenshot written to %s" % shot)
    for p in problems:
        print(p)
    print("atlas: %d sections, %d images, %d links inside the page, %d problems, %.1f s in the browser; "
          "screenshot %s" % (report["sections"], report["images"], report["internal_links"], len(problems),
                             time.monotonic() - t0, shot))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Re-evaluate a report's claims: python3 tools/verify_claims.py REPORT_DIR

Reads REPORT_DIR/data/claims.json (schema "steplab.claims/1", docs/json.md, "A report's claims")
and the data files its evidence names, and re-evaluates every claim with code of its own: the
rules in tools/claims_rules.py and, for membership's row tests, tools/claims_rows.py (pure
functions over values), reading the files and pointers and the claim loop here.  Prints
`<id>: <why>` for each claim that does not hold, then `claims: N, hold: H, do not hold: F,
theory: T` (T the sentences stated as theory, which have no rule).  Exit 0: every claim holds;
1: some claim does not; 2: claims.json missing, not JSON, not steplab.claims/1, or with a
`theory` that is not a list of {"section", "sentence"} strings (a file without `theory` is
accepted).  Standard library only.
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
if HERE not in sys.path:  # the rules' modules lie beside this file, whatever the working directory
    sys.path.insert(0, HERE)
from claims_rules import CHECKS, RULE_FIELDS, Fail, checked_rule, find, same_json, show
from claims_rows import check_membership

SCHEMA = "steplab.claims/1"
CLAIM_FIELDS = ("id", "section", "sentence", "kind", "rule", "evidence")

class BadClaimsFile(Exception): pass  # claims.json itself is unusable: exit status 2

def load_json(path):
    def reject(name):  # Python would otherwise accept NaN and Infinity
        raise ValueError("%s is not JSON" % name)
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_constant=reject)

def resolve(doc, pointer):
    """What `pointer` finds in doc; Fail if it finds nothing."""
    ok, found = find(doc, pointer)
    if not ok:
        raise Fail("pointer %s: %s" % (pointer, found))
    return found

class Report:
    """A report folder; data files are read once, relative to REPORT_DIR/data/."""
    def __init__(self, report_dir):
        self.data, self.cache = os.path.join(report_dir, "data"), {}

    def file(self, name):
        if not isinstance(name, str) or not name or os.path.isabs(name) \
                or ".." in name.replace("\\", "/").split("/"):
            raise Fail("file %s is not a path under data/" % show(name))
        if name not in self.cache:
            try:
                self.cache[name] = load_json(os.path.join(self.data, name))
            except FileNotFoundError:
                raise Fail("file %s is missing" % name)
            except (OSError, ValueError) as e:
                raise Fail("file %s is not readable JSON (%s)" % (name, e))
        return self.cache[name]

def differing(recorded, found):
    """The recorded value and the file's as a message shows them: whole where short; else, down
    arrays or objects of one shape (a map of verdicts), their first differing entry and its place."""
    a, b = show(recorded), show(found)
    if len(a) + len(b) <= 160:
        return a, b
    place = ""
    while True:
        if isinstance(recorded, list) and isinstance(found, list) and len(recorded) == len(found):
            keys = range(len(recorded))
        elif isinstance(recorded, dict) and isinstance(found, dict) and recorded.keys() == found.keys():
            keys = list(recorded)
        else:
            break
        k = next(k for k in keys if not same_json(recorded[k], found[k]))
        place, recorded, found = "%s/%s" % (place, k), recorded[k], found[k]
    cut = lambda v: show(v) if len(show(v)) <= 70 else show(v)[:70] + " ..."
    return cut(recorded) + (" at %s" % place if place else ""), cut(found)

# --- a claim and the file -----------------------------------------------------------------
def check_claim(report, doc, claim):
    if any(f not in claim for f in CLAIM_FIELDS):
        raise Fail("missing fields: %s" % ", ".join(f for f in CLAIM_FIELDS if f not in claim))
    kind, rule, evidence = claim["kind"], claim["rule"], claim["evidence"]
    if not isinstance(kind, str) or kind not in RULE_FIELDS:
        raise Fail("unknown kind %s" % show(kind))
    checked_rule(kind, rule)
    if not isinstance(evidence, list) or not all(isinstance(e, dict) for e in evidence):
        raise Fail("evidence is not a list of objects")
    problems, values = [], []
    for k, e in enumerate(evidence):  # every recorded value must still be the file's
        try:
            if any(f not in e for f in ("file", "pointer", "value")):
                raise Fail("lacks file, pointer or value")
            found = resolve(report.file(e["file"]), e["pointer"])
            values.append(found)
            if not same_json(found, e["value"]):
                problems.append("evidence %d (%s %s): recorded %s, the file holds %s"
                                % ((k, e["file"], e["pointer"]) + differing(e["value"], found)))
        except Fail as why:
            problems.append("evidence %d: %s" % (k, why))
    try:
        if kind == "membership":
            rows_at = lambda name, pointer: resolve(report.file(name), pointer)  # any selection's
            problems += check_membership(rows_at, doc.get("methods"), rule, evidence)
        elif len(values) == len(evidence):  # the other rules read the evidence's values
            problems += CHECKS[kind](rule, values)
    except Fail as why:
        problems.append(str(why))
    return problems

def load_claims(report_dir):
    """claims.json's document; BadClaimsFile (exit status 2) where it is unusable."""
    path = os.path.join(report_dir, "data", "claims.json")
    try:
        doc = load_json(path)
    except FileNotFoundError:
        raise BadClaimsFile("%s: missing" % path)
    except (OSError, ValueError) as e:
        raise BadClaimsFile("%s: not valid JSON (%s)" % (path, e))
    if not isinstance(doc, dict) or doc.get("schema") != SCHEMA \
            or not isinstance(doc.get("claims"), list):
        raise BadClaimsFile("%s: not a %s document with a claims array" % (path, SCHEMA))
    theory = doc.get("theory", [])  # optional, for files written before it
    if not isinstance(theory, list) or not all(isinstance(t, dict) and all(
            isinstance(t.get(f), str) for f in ("section", "sentence")) for t in theory):
        raise BadClaimsFile("%s: theory is not a list of objects with string section and "
                            "sentence" % path)
    return doc

def verify(report_dir, doc=None):
    """[(label, [problems])] per claim, [] where it holds; BadClaimsFile for exit status 2."""
    doc = load_claims(report_dir) if doc is None else doc
    report, seen, results = Report(report_dir), set(), []
    for i, claim in enumerate(doc["claims"]):
        cid = claim.get("id") if isinstance(claim, dict) else None
        label = cid if isinstance(cid, str) else "claims[%d]" % i
        try:
            if not isinstance(cid, str):  # also a claim that is not an object
                raise Fail("no string id")
            if cid in seen:
                raise Fail("duplicate id")
            seen.add(cid)
            problems = check_claim(report, doc, claim)
        except Fail as why:
            problems = [str(why)]
        except (TypeError, AttributeError, ValueError, KeyError, OverflowError) as e:  # malformed
            problems = ["cannot evaluate the rule (%s)" % e]
        results.append((label, problems))
    return results

def main(argv):
    if len(argv) != 2:
        print("usage: verify_claims.py REPORT_DIR", file=sys.stderr)
        return 2
    try:
        doc = load_claims(argv[1])
    except BadClaimsFile as e:
        print("verify_claims: %s; accepted: a JSON object with \"schema\": \"%s\", a "
              "\"claims\" array and, if any, a \"theory\" array of {\"section\", \"sentence\"} "
              "strings" % (e, SCHEMA), file=sys.stderr)
        return 2
    results = verify(argv[1], doc)
    failed = [(label, p) for label, p in results if p]
    for label, problems in failed:
        print("%s: %s" % (label, "; ".join(problems)))
    print("claims: %d, hold: %d, do not hold: %d, theory: %d"
          % (len(results), len(results) - len(failed), len(failed), len(doc.get("theory", []))))
    return 1 if failed else 0

if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Whether two reports reach the same verdicts: compares their data/claims.json claim by claim.

    tools/compare_verdicts.py REPORT_A REPORT_B

A verdict is what a claim decides, not the numbers it rests on (times move with the machine's
load): a membership claim's set, a trend's word, a statistic's words, a threshold's rows, a
comparison's winner, or that it is a tie, an equality's pairs, a count's number of its groups, an
extreme's holder and a mismatch's number of differing cells.
A comparison names solvers, not runs: its winner, or the set of solvers a tie names (with the
claims `<id>.tie.<solver>` that name each further one folded into it), each by the `method` or
`solver` field of the row its evidence points into; which of the tied solvers is the fastest, and
which of a solver's runs was its cheapest, is noise.
A ratio claim is a measured value, not a verdict: its verdict is how many ratios it spans (which
runs it is measured from is chosen by time too), so two reports whose ratios differ in value, or
were measured on other runs, agree on it. Prints
each claim whose verdict differs or that one report has and the other has not, and exits 1 if
any; 0 if every verdict is the same. Reads docs/json.md's schema steplab.claims/1 with the
standard library.
"""
import json
import sys


def row_name(report, evidence, cache):
    """The `method` or `solver` of the row an evidence pointer points into, else the pointer."""
    path, pointer = evidence.get("file", ""), evidence.get("pointer", "")
    if path not in cache:
        try:
            with open(f"{report}/data/{path}") as f:
                cache[path] = json.load(f)
        except (OSError, ValueError):
            cache[path] = None
    node = cache[path]
    for part in pointer.split("/")[1:-1]:
        part = part.replace("~1", "/").replace("~0", "~")
        if isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        elif isinstance(node, dict) and part in node:
            node = node[part]
        else:
            return path + "#" + pointer
    if isinstance(node, dict):
        for field in ("method", "solver"):
            if isinstance(node.get(field), str):
                return node[field]
    return path + "#" + pointer


def verdict(claim, names):
    rule, kind = claim.get("rule", {}), claim.get("kind")
    pointers = [e.get("file", "") + "#" + e.get("pointer", "") for e in claim.get("evidence", [])]
    if kind == "membership":
        return ("membership", sorted(rule.get("set", [])))
    if kind == "trend":
        return ("trend", rule.get("trend"))
    if kind == "statistic":
        return ("statistic", rule.get("words"))
    if kind == "threshold":
        return ("threshold", rule.get("op"), rule.get("limit"), sorted(pointers))
    if kind == "comparison":  # a winner, or the solvers a tie names
        a, others = rule.get("a"), rule.get("others") or []
        if not isinstance(a, int) or a >= len(names):
            return ("comparison", rule.get("relation"), None)
        if rule.get("relation") == "tie":
            tied = {names[a]} | ({names[others[0]]} if isinstance(others[0], int) and others[0] < len(names) else set())
            return ("comparison", "tie", sorted(tied))
        return ("comparison", rule.get("relation"), names[a])
    if kind == "count":  # how many of its groups hold
        return ("count", rule.get("count"), len(rule.get("groups", [])))
    if kind == "equality":  # the pairs it says are equal
        return ("equality", sorted(pointers))
    if kind == "extreme":  # which run holds the least or the greatest
        a = rule.get("a")
        return ("extreme", rule.get("which"), pointers[a] if isinstance(a, int) and a < len(pointers) else None)
    if kind == "mismatch":  # how many cells differ
        return ("mismatch", rule.get("count"))
    if kind == "ratio":  # a measured value, not a verdict: how many ratios it spans
        return ("ratio", len(rule.get("ratios", [])))
    return (kind, json.dumps(rule, sort_keys=True))


def load(report):
    """Each claim's verdict by id, a tie's further members (`<id>.tie.<solver>`) folded into it."""
    with open(f"{report}/data/claims.json") as f:
        claims = {c["id"]: c for c in json.load(f)["claims"]}
    cache, out = {}, {}
    for cid, c in claims.items():
        out[cid] = verdict(c, [row_name(report, e, cache) for e in c.get("evidence", [])])
    for cid in sorted(out):
        base, _, member = cid.rpartition(".tie.")
        if base and base in out and out[base][:2] == ("comparison", "tie") and out[cid][:2] == ("comparison", "tie"):
            out[base] = ("comparison", "tie", sorted(set(out[base][2]) | set(out[cid][2])))
            del out[cid]
    return out


def main(argv):
    if len(argv) != 3:
        print("usage: compare_verdicts.py REPORT_A REPORT_B", file=sys.stderr)
        return 2
    a, b = load(argv[1]), load(argv[2])
    differ = 0
    for cid in sorted(set(a) | set(b)):
        if cid not in a or cid not in b:
            print(f"{cid}: only in {argv[1] if cid in a else argv[2]}")
            differ += 1
        elif a[cid] != b[cid]:
            print(f"{cid}: {a[cid]} against {b[cid]}")
            differ += 1
    print(f"verdicts (a tie's members folded into it): {len(a)} and {len(b)}, verdicts that differ: {differ}")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

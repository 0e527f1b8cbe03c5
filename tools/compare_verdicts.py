#!/usr/bin/env python3
"""Whether two reports reach the same verdicts: compares their data/claims.json claim by claim.

    tools/compare_verdicts.py REPORT_A REPORT_B

A verdict is what a claim decides, not the numbers it rests on (times move with the machine's
load): a membership claim's set, a trend's word, a statistic's words, a threshold's rows, a
comparison's winner, or that it is a tie, an equality's pairs, a count's number of its groups, an
extreme's holder and a mismatch's number of differing cells.
A ratio claim is a measured value, not a verdict: its verdict is how many ratios it spans (which
runs it is measured from is chosen by time too), so two reports whose ratios differ in value, or
were measured on other runs, agree on it. Prints
each claim whose verdict differs or that one report has and the other has not, and exits 1 if
any; 0 if every verdict is the same. Reads docs/json.md's schema steplab.claims/1 with the
standard library.
"""
import json
import sys


def verdict(claim):
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
    if kind == "comparison":  # a winner, or a tie (which of the tied runs is named first is noise)
        if rule.get("relation") == "tie":
            return ("comparison", "tie")
        a = rule.get("a")
        return ("comparison", rule.get("relation"), pointers[a] if a is not None and a < len(pointers) else None)
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
    with open(f"{report}/data/claims.json") as f:
        return {c["id"]: c for c in json.load(f)["claims"]}


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
        elif verdict(a[cid]) != verdict(b[cid]):
            print(f"{cid}: {verdict(a[cid])} against {verdict(b[cid])}")
            differ += 1
    print(f"claims: {len(a)} and {len(b)}, verdicts that differ: {differ}")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

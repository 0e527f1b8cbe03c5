#!/usr/bin/env python3
"""Tests of tools/compare_verdicts.py: two reports' claims, the same verdicts or not."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "compare_verdicts.py")


def report(root, name, claims):
    os.makedirs(os.path.join(root, name, "data"))
    with open(os.path.join(root, name, "data", "claims.json"), "w") as f:
        json.dump({"schema": "steplab.claims/1", "methods": [], "claims": claims}, f)
    return os.path.join(root, name)


def cheapest(cid, relation, winner, value):
    ev = [{"file": "cost/w.json", "pointer": f"/points/{winner}/seconds", "value": value},
          {"file": "cost/w.json", "pointer": "/points/9/seconds", "value": 2 * value}]
    return {"id": cid, "section": "cost", "sentence": "s", "kind": "comparison",
            "rule": {"a": 0, "others": [1], "relation": relation, "margin": 1.5, "noise": []}, "evidence": ev}


def members(cid, names):
    return {"id": cid, "section": "answers", "sentence": "s", "kind": "membership", "rule": {"set": names}, "evidence": []}


def count(cid, n, values):  # a count over comparison groups whose times differ between runs
    groups = [{"kind": "comparison", "rule": {"a": 2 * i, "others": [2 * i + 1], "relation": "tie", "margin": 1.5, "noise": []}}
              for i in range(len(values) // 2)]
    ev = [{"file": "scaling/m.json", "pointer": f"/rows/{i}/seconds", "value": v} for i, v in enumerate(values)]
    return {"id": cid, "section": "scaling", "sentence": "s", "kind": "count", "rule": {"groups": groups, "count": n}, "evidence": ev}


def run(a, b):
    p = subprocess.run([sys.executable, TOOL, a, b], capture_output=True, text=True)
    return p.returncode, p.stdout


class CompareVerdicts(unittest.TestCase):
    def test_times_differ_verdicts_agree(self):
        with tempfile.TemporaryDirectory() as d:
            a = report(d, "a", [cheapest("c1", "less", 3, 1.0), members("m1", ["x", "y"]), cheapest("c2", "tie", 4, 1.0)])
            b = report(d, "b", [cheapest("c1", "less", 3, 1.7), members("m1", ["y", "x"]), cheapest("c2", "tie", 5, 0.4)])
            code, out = run(a, b)
            self.assertEqual(code, 0, out)
            self.assertIn("verdicts that differ: 0", out)

    def test_a_flip_is_named(self):
        with tempfile.TemporaryDirectory() as d:
            a = report(d, "a", [cheapest("c1", "less", 3, 1.0), members("m1", ["x"]), cheapest("c3", "less", 1, 1.0)])
            b = report(d, "b", [cheapest("c1", "tie", 3, 1.0), members("m1", ["x", "z"]), cheapest("c3", "less", 2, 1.0)])
            code, out = run(a, b)
            self.assertEqual(code, 1)
            for cid in ("c1", "m1", "c3"):
                self.assertIn(cid + ":", out)
            self.assertIn("verdicts that differ: 3", out)

    def test_a_count_compares_its_number_not_its_times(self):
        with tempfile.TemporaryDirectory() as d:
            a = report(d, "a", [count("k1", 2, [1.0, 1.2, 2.0, 2.1]), count("k2", 1, [1.0, 1.2, 1.0, 3.0])])
            b = report(d, "b", [count("k1", 2, [1.1, 1.3, 2.2, 2.0]), count("k2", 2, [1.0, 1.2, 1.0, 1.4])])
            code, out = run(a, b)
            self.assertEqual(code, 1)
            self.assertNotIn("k1:", out)
            self.assertIn("k2: ('count', 1, 2) against ('count', 2, 2)", out)

    def test_a_claim_in_one_report_only(self):
        with tempfile.TemporaryDirectory() as d:
            a = report(d, "a", [members("m1", ["x"]), members("m2", ["y"])])
            b = report(d, "b", [members("m1", ["x"])])
            code, out = run(a, b)
            self.assertEqual(code, 1)
            self.assertIn("m2: only in", out)


if __name__ == "__main__":
    unittest.main()

#!/usr/bin/env python3
"""Tests of tools/compare_verdicts.py: two reports' claims, the same verdicts or not."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "compare_verdicts.py")


# The data file the comparisons point into: runs 3, 4 and 5 are rk4's, 1 rk3's, 2 and 9 dopri5's.
POINTS = [{"method": m} for m in ("rk3", "rk3", "dopri5", "rk4", "rk4", "rk4", "x", "x", "x", "dopri5")]


def report(root, name, claims):
    os.makedirs(os.path.join(root, name, "data", "cost"))
    with open(os.path.join(root, name, "data", "claims.json"), "w") as f:
        json.dump({"schema": "steplab.claims/1", "methods": [], "claims": claims}, f)
    with open(os.path.join(root, name, "data", "cost", "w.json"), "w") as f:
        json.dump({"points": POINTS}, f)
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


def ratio(cid, least, greatest, values, levels=(0, 1)):  # the peer's over steplab's at each level
    ev = [{"file": "cost/peers.json", "pointer": f"/levels/{i}/{who}", "value": v}
          for i, pair in zip(levels, values) for who, v in zip(("peer", "steplab"), pair)]
    ratios = [{"over": [2 * k], "under": [2 * k + 1]} for k in range(len(values))]
    return {"id": cid, "section": "cost", "sentence": "s", "kind": "ratio",
            "rule": {"ratios": ratios, "least": least, "greatest": greatest, "digits": {"decimals": 2}}, "evidence": ev}


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

    def test_a_tie_is_its_solvers_with_its_further_members_folded_in(self):
        def tie(cid, a, b):  # a tie of the runs at points a and b
            ev = [{"file": "cost/w.json", "pointer": f"/points/{i}/seconds", "value": 1.0} for i in (a, b)]
            return {"id": cid, "section": "cost", "sentence": "s", "kind": "comparison",
                    "rule": {"a": 0, "others": [1], "relation": "tie", "margin": 1.5, "noise": []}, "evidence": ev}
        with tempfile.TemporaryDirectory() as d:
            # t1: rk4, dopri5 and rk3 in both, named in other roles and by other runs of rk4
            # t2: rk3 is a further member in a only
            a = report(d, "a", [tie("t1", 3, 9), tie("t1.tie.rk3", 3, 1), tie("t2", 3, 9), tie("t2.tie.rk3", 3, 1)])
            b = report(d, "b", [tie("t1", 1, 4), tie("t1.tie.dopri5", 1, 2), tie("t2", 5, 9)])
            code, out = run(a, b)
            self.assertEqual(code, 1, out)
            self.assertNotIn("t1", out)
            self.assertIn("t2: ('comparison', 'tie', ['dopri5', 'rk3', 'rk4']) against ('comparison', 'tie', ['dopri5', 'rk4'])", out)
            self.assertIn("verdicts that differ: 1", out)

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

    def test_a_ratio_is_a_value_not_a_verdict(self):
        with tempfile.TemporaryDirectory() as d:
            a = report(d, "a", [ratio("r1", "0.87", "2.57", [(0.434, 0.5), (2.566, 1.0)]),
                                ratio("r2", "1.50", "1.50", [(1.5, 1.0)]),
                                ratio("r3", "1.50", "1.50", [(1.5, 1.0)])])
            b = report(d, "b", [ratio("r1", "1.20", "3.10", [(0.6, 0.5), (3.1, 1.0)]),  # other values
                                ratio("r2", "1.50", "1.50", [(1.5, 1.0)], levels=(1,)),  # another run chosen
                                ratio("r3", "0.87", "2.57", [(0.434, 0.5), (2.566, 1.0)])])  # a range of two
            code, out = run(a, b)
            self.assertEqual(code, 1)
            self.assertNotIn("r1:", out)
            self.assertNotIn("r2:", out)
            self.assertIn("r3: ('ratio', 1) against ('ratio', 2)", out)
            self.assertIn("verdicts that differ: 1", out)

    def test_a_membership_with_and_is_its_set(self):
        def with_and(cid, names, limit, more=None):  # an intersection; its selections' values move
            claim = members(cid, names)
            claim["rule"]["and"] = more if more is not None else [
                {"file": "cost/w.json", "rows": "/points", "where": {}, "key": "method", "over": "numerical",
                 "test": {"field": "/seconds", "op": "<", "value": limit}}]
            return claim
        with tempfile.TemporaryDirectory() as d:
            a = report(d, "a", [with_and("m1", ["x", "y"], 2), with_and("m2", ["x"], 2), with_and("m3", [], 1, 3)])
            b = report(d, "b", [with_and("m1", ["y", "x"], 3), with_and("m2", ["x", "z"], 2), with_and("m3", [], 1, [])])
            code, out = run(a, b)
            self.assertEqual(code, 1, out)
            self.assertNotIn("m1:", out)
            self.assertIn("m2: ('membership', ['x']) against ('membership', ['x', 'z'])", out)
            self.assertNotIn("m3:", out)  # a malformed and: no crash, the set decides
            self.assertIn("verdicts that differ: 1", out)

    def test_a_claim_in_one_report_only(self):
        with tempfile.TemporaryDirectory() as d:
            a = report(d, "a", [members("m1", ["x"]), members("m2", ["y"])])
            b = report(d, "b", [members("m1", ["x"])])
            code, out = run(a, b)
            self.assertEqual(code, 1)
            self.assertIn("m2: only in", out)


if __name__ == "__main__":
    unittest.main()

"""Tests of tools/verify_claims.py: python3 tools/verify_claims_test.py

Each test writes a small report folder (data/claims.json and a made-up data file or two) in a
temporary directory and runs the verifier's functions or its command line on it: membership claims
(rows read from a file, and with `and` from two files), a ratio claim end to end, evidence and pointers, the claim loop and the
command line.  The other kinds' rule checks: tools/claims_rules_test.py; the row-test language:
tools/claims_rows_test.py.
"""
import copy
import json
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
if HERE not in sys.path:
    sys.path.insert(0, HERE)
import claims_rules as cr  # the rules, pure functions over values
import verify_claims as vc  # the files, the claim loop and the command line
from claims_test_fixtures import (ABOVE, BELOW, COST, PEERS, SCRIPT, SF, STABILITY, Folder, comparison, count,
                                  equality, ev, ratio, spearman, threshold, trend)

STABLE = {"field": "/stable", "op": "==", "value": True}


def membership(cid="M1", over="numerical", names=("backward_euler", "trapezoid"), rows=(0, 1, 2),
               test=STABLE, fields=("stable",)):
    """Evidence: each of `fields` of each of `rows` that the sweep row has, rows outermost."""
    return {"id": cid, "section": "stability", "sentence": "stable at dt 0.5: ...", "kind": "membership",
            "rule": {"file": SF, "rows": "/sweep", "where": {"dt": 0.5}, "key": "method", "over": over,
                     "test": test, "set": list(names)},
            "evidence": [ev("/sweep/%d/%s" % (i, f), STABILITY["sweep"][i][f]) for i in rows for f in fields
                         if f in STABILITY["sweep"][i]]}


class Membership(Folder):
    def test_holds_and_mutation(self):
        # dt 0.5, numerical rows 0..2: stable false, true, true -> {backward_euler, trapezoid}
        self.assertEqual(self.problems(membership()), {"M1": []})
        # flip forward_euler's stable at dt 0.5: the set becomes {forward_euler, backward_euler,
        # trapezoid} and evidence 0 (recorded false) no longer matches the file (true)
        flipped = copy.deepcopy(STABILITY)
        flipped["sweep"][0]["stable"] = True
        p = self.problems(membership(), stability=flipped)["M1"]
        self.assertEqual(len(p), 2, p)
        self.write([membership()], flipped)
        out = self.run_cli()
        self.assertEqual(out.returncode, 1)
        self.assertIn("M1: ", out.stdout)
        self.assertIn("forward_euler", out.stdout)
        self.assertIn("claims: 1, hold: 0, do not hold: 1, theory: 0", out.stdout)

    def test_exact_flow_left_out_by_numerical(self):
        # row 3 (exact, stable) passes `where` but not over "numerical": neither set nor evidence
        self.assertEqual(self.problems(membership())["M1"], [])
        self.assertTrue(self.problems(membership(rows=(0, 1, 2, 3)))["M1"])  # extra evidence
        # over "all": the exact flow counts, with its evidence
        self.assertTrue(self.problems(membership(over="all"))["M1"])
        full = membership(over="all", names=("backward_euler", "trapezoid", "exact"), rows=(0, 1, 2, 3))
        self.assertEqual(self.problems(full)["M1"], [])
        self.assertTrue(self.problems(membership(over="some"))["M1"])

    def test_evidence_one_per_row(self):
        self.assertTrue(self.problems(membership(rows=(1, 2)))["M1"])  # row 0 has no item
        self.assertTrue(self.problems(membership(rows=(0, 1, 2, 2)))["M1"])  # row 2 twice
        self.assertEqual(self.problems(membership(rows=(2, 0, 1)))["M1"], [])  # in any order

    def test_pointer_per_row(self):
        # "stable and growth < 1": rows 0 (false, 3.2), 1 (true, 0.9), 2 (true, no growth: false)
        both = {"all": [STABLE, {"field": "/growth", "op": "<", "value": 1}]}
        full = membership(names=["backward_euler"], test=both, fields=("stable", "growth"))
        self.assertEqual(len(full["evidence"]), 5)  # row 2 has no growth: no item for it
        self.assertEqual(self.problems(full)["M1"], [])
        # the items of one pointer only: the growth of rows 0 and 1 are missing
        p = self.problems(membership(names=["backward_euler"], test=both))["M1"]
        self.assertEqual(p, ['evidence should be one item per row: 5 expected, 3 given, missing '
                             '["/sweep/0/growth", "/sweep/1/growth"], extra []'])
        # an item for a pointer that finds nothing in its row (also a missing file value)
        extra = copy.deepcopy(full)
        extra["evidence"].append(ev("/sweep/2/growth", None))
        p = self.problems(extra)["M1"]
        self.assertIn("evidence 5: pointer /sweep/2/growth: no member", p[0])
        self.assertIn('extra ["/sweep/2/growth"]', p[1])
        # a pointer twice in the test still asks for one item per row
        twice = {"any": [STABLE, {"not": STABLE}]}
        all_three = ["forward_euler", "backward_euler", "trapezoid"]
        self.assertEqual(self.problems(membership(names=all_three, test=twice))["M1"], [])
        # another file than the rule's
        other = membership()
        other["evidence"][0]["file"] = "stability/../stability/stability.json"
        self.assertTrue(self.problems(other)["M1"])

    def test_not_with_a_missing_pointer(self):
        # "not growth > 1": row 0 (3.2) fails, row 1 (0.9) and row 2 (no growth) hold
        test = {"not": {"field": "/growth", "op": ">", "value": 1}}
        claim = membership(test=test, fields=("growth",))
        self.assertEqual([e["pointer"] for e in claim["evidence"]], ["/sweep/0/growth", "/sweep/1/growth"])
        self.assertEqual(self.problems(claim)["M1"], [])
        p = self.problems(membership(names=["backward_euler"], test=test, fields=("growth",)))["M1"]
        self.assertEqual(p, ['set is ["backward_euler"], the rows give ["backward_euler", "trapezoid"]'])

    def test_scaled(self):
        # "growth < c dt" at dt 0.5: rows 0 (3.2, 0.5), 1 (0.9, 0.5), 2 (no growth: false)
        test = lambda c: {"scaled": ["/growth", "/dt"], "op": "<", "times": c}
        claim = membership(names=["backward_euler"], test=test(2), fields=("growth", "dt"))
        self.assertEqual([e["pointer"] for e in claim["evidence"]],  # row 2: its dt only
                         ["/sweep/0/growth", "/sweep/0/dt", "/sweep/1/growth", "/sweep/1/dt", "/sweep/2/dt"])
        self.assertEqual(self.problems(claim)["M1"], [])  # 0.9 < 1 <= 3.2
        p = self.problems(membership(names=["backward_euler"], test=test(7), fields=("growth", "dt")))["M1"]
        self.assertEqual(p, ['set is ["backward_euler"], the rows give ["backward_euler", "forward_euler"]'])
        self.assertEqual(self.problems(membership(names=[], test=test(1.8), fields=("growth", "dt")))["M1"], [])
        # the scaled test's pointers count in the evidence: its P1 alone is not enough
        p = self.problems(membership(names=["backward_euler"], test=test(2), fields=("growth",)))["M1"]
        self.assertEqual(p, ['evidence should be one item per row: 5 expected, 2 given, missing '
                             '["/sweep/0/dt", "/sweep/1/dt", "/sweep/2/dt"], extra []'])
        # nested in all: the pointers of both tests, each once per row
        both = {"all": [STABLE, test(2)]}
        claim = membership(names=["backward_euler"], test=both, fields=("stable", "growth", "dt"))
        self.assertEqual(len(claim["evidence"]), 8)
        self.assertEqual(self.problems(claim)["M1"], [])
        # a malformed scaled test: the claim does not hold
        p = self.problems(membership(test={"scaled": ["/growth", "/dt"], "op": "<", "value": 2}))["M1"]
        self.assertEqual(len(p), 1, p)
        self.assertIn("or no times", p[0])
        # the file changes: backward_euler's growth 0.9 becomes 1.1, above 2 x 0.5
        moved = copy.deepcopy(STABILITY)
        moved["sweep"][1]["growth"] = 1.1
        claim = membership(names=["backward_euler"], test=test(2), fields=("growth", "dt"))
        p = self.problems(claim, stability=moved)["M1"]
        self.assertIn("recorded 0.9, the file holds 1.1", p[0])
        self.assertEqual(p[1], 'set is ["backward_euler"], the rows give []')
        self.write([claim], moved)
        out = self.run_cli()
        self.assertEqual(out.returncode, 1)
        self.assertTrue(out.stdout.startswith("M1: "), out.stdout)

    def test_scaled_infinity_and_null(self):
        # thresholds, numerical: stable_again_measured > 10 dt_measured: forward_euler (never, 0.2)
        # and rk4 (never, 0.2183) hold, +infinity; backward_euler and trapezoid (null, unbounded) do not
        rows = [0, 1, 2, 3]
        fields = ("stable_again_measured", "dt_measured")
        claim = {"id": "M2", "section": "stability", "sentence": "...", "kind": "membership",
                 "rule": {"file": SF, "rows": "/thresholds", "where": {}, "key": "method", "over": "numerical",
                          "test": {"scaled": list("/" + f for f in fields), "op": ">", "times": 10},
                          "set": ["rk4", "forward_euler"]},
                 "evidence": [ev("/thresholds/%d/%s" % (i, f), STABILITY["thresholds"][i][f])
                              for i in rows for f in fields]}
        self.assertEqual(self.problems(claim)["M2"], [])
        # the other way round: dt_measured > 10 stable_again: 0.2 > +infinity fails, null fails
        swapped = copy.deepcopy(claim)
        swapped["rule"]["test"]["scaled"].reverse()
        p = self.problems(swapped)["M2"]
        self.assertEqual(p, ['set is ["forward_euler", "rk4"], the rows give []'])
        # over "all": the exact flow's row (4) passes too, and needs its items
        every = copy.deepcopy(claim)
        every["rule"]["over"] = "all"
        p = self.problems(every)["M2"]
        self.assertEqual(p, ['evidence should be one item per row: 10 expected, 8 given, missing '
                             '["/thresholds/4/stable_again_measured", "/thresholds/4/dt_measured"], extra []'])

    def test_malformed_test(self):
        for bad in [{"field": "/stable", "op": "=~", "value": True}, {"field": "stable", "op": "==", "value": 1},
                    {"field": "/stable", "op": "=="}, {"difference": ["/dt"], "op": "<", "value": 1},
                    {"field": "/stable", "op": "==", "value": True, "not": STABLE}, {"any": STABLE},
                    {"not": {"field": "/a~2", "op": "!=", "value": 0}}, [STABLE]]:
            p = self.problems(membership(test=bad))["M1"]
            self.assertEqual(len(p), 1, (bad, p))
            self.assertIn("test ", p[0])
        p = self.problems(membership(test={"difference": ["/dt", "/growth"], "op": "==", "value": 0}))["M1"]
        self.assertIn('op not one of "<", "<=", ">", ">="', p[0])

    def test_and_over_two_files_and_mutation(self):
        # stable at dt 0.5 (stability.json: backward_euler, trapezoid) and, in cost.json, a
        # cheapest run under 2 s (numerical rows 0..3: rk4 1.0, trapezoid 1.5, backward_euler
        # 1.05; forward_euler null; leapfrog, row 4, is none of the methods)
        fast = {"file": "cost.json", "rows": "/cheapest", "where": {}, "key": "method", "over": "numerical",
                "test": {"field": "/seconds", "op": "<", "value": 2}}
        claim = membership("MA")
        claim["rule"]["and"] = [fast]
        claim["evidence"] += [ev("/cheapest/%d/seconds" % i, COST["cheapest"][i]["seconds"], "cost.json")
                              for i in range(4)]
        claims = [claim, membership(), trend("T1", [1, 2], "stays unbounded")]
        self.assertEqual(self.problems(*claims), {"MA": [], "M1": [], "T1": []})
        # trapezoid's cheapest run now takes 2.5 s: it drops out of the intersection
        slower = copy.deepcopy(COST)
        slower["cheapest"][1]["seconds"] = 2.5
        p = self.problems(*claims, cost=slower)
        self.assertEqual((p["M1"], p["T1"]), ([], []))
        self.assertEqual(len(p["MA"]), 2, p["MA"])
        self.assertIn("(cost.json /cheapest/1/seconds): recorded 1.5, the file holds 2.5", p["MA"][0])
        self.assertEqual(p["MA"][1], 'set is ["backward_euler", "trapezoid"], the rows give ["backward_euler"] '
                         '(the rule\'s ["backward_euler", "trapezoid"], and[0]\'s ["backward_euler", "rk4"])')
        self.cli_names_only(claims, "MA", cost=slower)
        # the and's items left out of the evidence, or one named in the other file: it does not hold
        short, moved = dict(copy.deepcopy(claim), id="MB"), dict(copy.deepcopy(claim), id="MC")
        del short["evidence"][-1]
        moved["evidence"][-1]["file"] = SF
        p = self.problems(short, moved)
        self.assertEqual(p["MB"], ['evidence should be one item per row: 7 expected, 6 given, missing '
                                   '["cost.json#/cheapest/3/seconds"], extra []'])
        self.assertIn("evidence 6: pointer /cheapest/3/seconds: no member", p["MC"][0])
        self.assertIn('missing ["cost.json#/cheapest/3/seconds"], extra ["%s#/cheapest/3/seconds"]' % SF, p["MC"][1])


class Ratio(Folder):
    def test_end_to_end_and_mutation(self):
        # the peer's over steplab's at three error levels: 2.555, 2.566, 0.868, printed as the range
        # "0.87" to "2.57"; and the one at the first level alone, "2.56"
        claims = [ratio("R1", [0, 1, 2], "0.87", "2.57"), ratio("R2", [0], "2.56"),
                  trend("T1", [1, 2], "stays unbounded")]
        self.write(claims)
        out = self.run_cli()
        self.assertEqual((out.returncode, out.stdout), (0, "claims: 3, hold: 3, do not hold: 0, theory: 0\n"))
        # the peer's run at the third level now takes 0.5, not 0.434: the least ratio is 1, not
        # "0.87"; R2 reads no value of that level and still holds
        moved = copy.deepcopy(PEERS)
        moved["levels"][2]["peer"] = 0.5
        p = self.problems(*claims, peers=moved)
        self.assertEqual((p["R2"], p["T1"]), ([], []))
        self.assertEqual(len(p["R1"]), 2, p["R1"])
        self.assertIn("evidence 4 (cost/peers.json /levels/2/peer): recorded 0.434, the file holds 0.5", p["R1"][0])
        self.assertIn('the least ratio 1 (ratio 2) is not "0.87" to 2 decimals', p["R1"][1])
        self.cli_names_only(claims, "R1", peers=moved)
        # a value that becomes "unbounded" (a run that never reached the level) fails it too
        moved["levels"][2]["peer"] = "unbounded"
        self.assertIn('evidence 4 is "unbounded", not a finite number', self.problems(*claims, peers=moved)["R1"])


class Evidence(Folder):
    def test_pointer(self):
        doc = {"a/b": {"m~n": [10, 20]}, "": 3}
        self.assertEqual(vc.resolve(doc, "/a~1b/m~0n/1"), 20)
        self.assertEqual(vc.resolve(doc, "/"), 3)
        self.assertIs(vc.resolve(doc, ""), doc)
        for bad in ["/a~1b/m~0n/01", "/a~1b/m~0n/2", "/a~2b", "a", "/a~1b/m~0n/-"]:
            self.assertRaises(cr.Fail, vc.resolve, doc, bad)

    def test_does_not_hold(self):
        wrong = trend("E1", [1, 2], "stays unbounded")
        wrong["evidence"][0]["value"] = 0.5  # the file holds "unbounded"
        gone = trend("E2", [1, 2], "stays unbounded")
        gone["evidence"][1]["pointer"] = "/thresholds/9/dt_measured"
        unknown = dict(trend("E3", [1, 2], "stays unbounded"), kind="ranking")
        nofile = trend("E4", [1, 2], "stays unbounded")
        nofile["evidence"][0]["file"] = "stability/none.json"
        kendall = spearman("E5")
        kendall["rule"]["statistic"] = "kendall"
        bare = trend("E6", [1, 2], "stays unbounded")
        del bare["sentence"]
        p = self.problems(wrong, gone, unknown, nofile, kendall, bare)
        self.assertIn('recorded 0.5, the file holds "unbounded"', p["E1"][0])
        self.assertIn("no element 9", p["E2"][0])
        self.assertIn("unknown kind", p["E3"][0])
        self.assertIn("missing", p["E4"][0])
        self.assertIn("unknown statistic", p["E5"][0])
        self.assertIn("sentence", p["E6"][0])

    def test_duplicate_id(self):
        self.write([membership("D"), trend("D", [1, 2], "stays unbounded")])
        self.assertEqual(vc.verify(self.dir), [("D", []), ("D", ["duplicate id"])])


class CommandLine(Folder):
    def test_exit_statuses(self):
        self.write([membership(), trend("T1", [1, 2], "stays unbounded"), spearman(),
                    threshold("H1", [0, 3], "<", 0.25), comparison("C1", "less", 1.3, 0, [1]),
                    equality("Q1", [[2, 3]]), count("N1", [BELOW, ABOVE], 1), ratio("R1", [0, 1, 2], "0.87", "2.57")])
        out = self.run_cli()
        self.assertEqual((out.returncode, out.stdout), (0, "claims: 8, hold: 8, do not hold: 0, theory: 0\n"))
        self.write([membership(), trend("T1", [1, 2], "rises")])
        out = self.run_cli()
        self.assertEqual(out.returncode, 1)
        self.assertTrue(out.stdout.startswith("T1: "), out.stdout)
        os.remove(os.path.join(self.dir, "data", "claims.json"))
        out = self.run_cli()
        self.assertEqual(out.returncode, 2)
        self.assertIn("claims.json: missing", out.stderr)
        for raw in ["{not json", json.dumps({"schema": "steplab.claims/2", "claims": []})]:
            self.write([], raw=raw)
            out = self.run_cli()
            self.assertEqual(out.returncode, 2)
            self.assertIn("steplab.claims/1", out.stderr)

    def test_theory(self):
        theory = [{"section": "stability", "sentence": "Backward Euler is A-stable."},
                  {"section": "methods", "sentence": "RK4 is of order 4.", "source": "textbook"}]
        self.write([trend("T1", [1, 2], "stays unbounded")], theory=theory)
        out = self.run_cli()
        self.assertEqual((out.returncode, out.stdout), (0, "claims: 1, hold: 1, do not hold: 0, theory: 2\n"))
        self.write([trend("T1", [1, 2], "rises")], theory=[])
        out = self.run_cli()
        self.assertEqual(out.returncode, 1)
        self.assertTrue(out.stdout.endswith("claims: 1, hold: 0, do not hold: 1, theory: 0\n"), out.stdout)

    def test_any_working_directory(self):
        # the command line finds claims_rules.py beside it from another directory, REPORT_DIR relative
        self.write([membership(), trend("T1", [1, 2], "stays unbounded")])
        out = subprocess.run([sys.executable, os.path.relpath(SCRIPT, self.dir), "."], cwd=self.dir,
                             capture_output=True, text=True)
        self.assertEqual((out.returncode, out.stdout, out.stderr),
                         (0, "claims: 2, hold: 2, do not hold: 0, theory: 0\n", ""))
        out = subprocess.run([sys.executable, SCRIPT, os.path.basename(self.dir)],
                             cwd=os.path.dirname(self.dir), capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stderr)

    def test_malformed_theory(self):
        for theory in [{"section": "s", "sentence": "x"}, "x", None, [["s", "x"]], [{"section": "s"}],
                       [{"section": "s", "sentence": 3}], [{"section": None, "sentence": "x"}],
                       [{"section": "s", "sentence": "x"}, 1]]:
            self.write([trend("T1", [1, 2], "stays unbounded")], theory=theory)
            out = self.run_cli()
            self.assertEqual((out.returncode, out.stdout), (2, ""), theory)
            self.assertIn("theory is not a list of objects with string section and sentence", out.stderr)
            self.assertRaises(vc.BadClaimsFile, vc.verify, self.dir)


if __name__ == "__main__":
    unittest.main()

"""Tests of tools/verify_claims.py: python3 -m unittest tools/verify_claims_test.py

Each test writes a small report folder (data/claims.json and a made-up data file or two) in a
temporary directory and runs the verifier's functions or its command line on it.
"""
import copy
import importlib.util
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "verify_claims.py")
_spec = importlib.util.spec_from_file_location("verify_claims", SCRIPT)
vc = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(vc)
INF = math.inf

METHODS = [{"name": n, "family": f, "order": o, "symplectic": False, "exact_flow": n == "exact"}
           for n, f, o in [("forward_euler", "euler", 1), ("backward_euler", "euler", 1),
                           ("trapezoid", "theta", 2), ("rk4", "rk", 4), ("exact", "exact", 0)]]
STABILITY = {
    "schema": "steplab.stability/2",
    "thresholds": [  # 0..4
        {"method": "forward_euler", "dt_measured": 0.2, "stable_again_measured": "never"},
        {"method": "backward_euler", "dt_measured": "unbounded", "stable_again_measured": None},
        {"method": "trapezoid", "dt_measured": "unbounded", "stable_again_measured": None},
        {"method": "rk4", "dt_measured": 0.2183, "stable_again_measured": "never"},
        {"method": "exact", "dt_measured": "unbounded", "stable_again_measured": None}],
    "sweep": [  # rows 0..3 at dt 0.5, row 4 at dt 0.1
        {"method": "forward_euler", "dt": 0.5, "stable": False},
        {"method": "backward_euler", "dt": 0.5, "stable": True},
        {"method": "trapezoid", "dt": 0.5, "stable": True},
        {"method": "exact", "dt": 0.5, "stable": True},
        {"method": "forward_euler", "dt": 0.1, "stable": True}],
}
# Spearman points: x = [1, 2, 2, unbounded], y = [0.5, never, 0.1, 0.3]
STATS = {"x": [1, 2, 2, "unbounded"], "y": [0.5, "never", 0.1, 0.3]}
SF = "stability/stability.json"
# Each solver's cheapest run reaching an error level: run time and the two runs' spread
COST = {"cheapest": [  # 0..4
    {"method": "rk4", "seconds": 1.0, "seconds_spread": 1.1},
    {"method": "trapezoid", "seconds": 1.5, "seconds_spread": 1.2},
    {"method": "backward_euler", "seconds": 1.05, "seconds_spread": 1.02},
    {"method": "forward_euler", "seconds": None, "seconds_spread": None},
    {"method": "leapfrog", "seconds": "never", "seconds_spread": 1.0}]}


def ev(pointer, value, file=SF):
    return {"file": file, "pointer": pointer, "value": value}


def membership(cid="M1", over="numerical", names=("backward_euler", "trapezoid"), rows=(0, 1, 2)):
    return {"id": cid, "section": "stability", "sentence": "stable at dt 0.5: ...", "kind": "membership",
            "rule": {"file": SF, "rows": "/sweep", "where": {"dt": 0.5}, "key": "method", "over": over,
                     "field": "stable", "equals": True, "set": list(names)},
            "evidence": [ev("/sweep/%d/stable" % i, STABILITY["sweep"][i]["stable"]) for i in rows]}


def trend(cid, rows, word, relative=1e-3, field="dt_measured"):
    return {"id": cid, "section": "stability", "sentence": "dt* ...", "kind": "trend",
            "rule": {"along": [STABILITY["thresholds"][i]["method"] for i in rows], "relative": relative,
                     "trend": word},
            "evidence": [ev("/thresholds/%d/%s" % (i, field), STABILITY["thresholds"][i][field]) for i in rows]}


def spearman(cid="S1", value=-0.32, decimals=2, words="moderate negative"):
    return {"id": cid, "section": "cost", "sentence": "rho ...", "kind": "statistic",
            "rule": {"statistic": "spearman", "x": [0, 1, 2, 3], "y": [4, 5, 6, 7], "value": value,
                     "decimals": decimals, "words": words},
            "evidence": [ev("/%s/%d" % (k, i), STATS[k][i], "stats.json") for k in "xy" for i in range(4)]}


def threshold(cid, rows, op, limit, field="dt_measured"):
    return {"id": cid, "section": "stability", "sentence": "dt* ...", "kind": "threshold",
            "rule": {"op": op, "limit": limit},
            "evidence": [ev("/thresholds/%d/%s" % (i, field), STABILITY["thresholds"][i][field]) for i in rows]}


def comparison(cid, relation, margin, a, others, noise=()):
    """Evidence: row a's seconds, then each of others' seconds, then each of noise's spreads."""
    rows = [a] + list(others)
    return {"id": cid, "section": "cost", "sentence": "cheapest ...", "kind": "comparison",
            "rule": {"a": 0, "others": list(range(1, len(rows))), "relation": relation, "margin": margin,
                     "noise": list(range(len(rows), len(rows) + len(noise)))},
            "evidence": [ev("/cheapest/%d/seconds" % r, COST["cheapest"][r]["seconds"], "cost.json") for r in rows]
            + [ev("/cheapest/%d/seconds_spread" % r, COST["cheapest"][r]["seconds_spread"], "cost.json")
               for r in noise]}


class Folder(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, claims, stability=STABILITY, raw=None, cost=COST):
        os.makedirs(os.path.join(self.dir, "data", "stability"), exist_ok=True)
        for name, doc in [(SF, stability), ("stats.json", STATS), ("cost.json", cost)]:
            with open(os.path.join(self.dir, "data", name), "w") as f:
                json.dump(doc, f)
        with open(os.path.join(self.dir, "data", "claims.json"), "w") as f:
            f.write(raw if raw is not None else
                    json.dumps({"schema": "steplab.claims/1", "methods": METHODS, "claims": claims}))

    def problems(self, *claims, stability=STABILITY, cost=COST):
        self.write(list(claims), stability, cost=cost)
        return dict(vc.verify(self.dir))

    def run_cli(self):
        return subprocess.run([sys.executable, SCRIPT, self.dir], capture_output=True, text=True)


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
        self.assertIn("claims: 1, hold: 0, do not hold: 1", out.stdout)

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


class Trend(Folder):
    def test_words(self):
        self.assertEqual(vc.trend_of([INF, INF], 1e-3), "stays unbounded")
        self.assertEqual(vc.trend_of([INF, 0.2183], 1e-3), "falls")  # inf is never a number
        self.assertEqual(vc.trend_of([0.2183, INF], 1.0), "rises")
        # |0.5 - 0.50001| = 1e-5 <= 1e-3 * 0.50001
        self.assertEqual(vc.trend_of([0.5, 0.50001], 1e-3), "stays the same")
        self.assertEqual(vc.trend_of([0.5, 0.50001], 1e-6), "rises")  # 1e-5 > 5.0001e-7
        self.assertEqual(vc.trend_of([0.1, 0.2, 0.15], 1e-3), "does not move one way")
        self.assertEqual(vc.trend_of([1.0, None], 1e-3), "not measured")
        self.assertEqual(vc.trend_of([INF, None], 1e-3), "not measured")

    def test_claims(self):
        p = self.problems(trend("T1", [1, 2], "stays unbounded"),  # [inf, inf]
                          trend("T2", [2, 3], "falls"),  # [inf, 0.2183]
                          trend("T3", [2, 0], "stays the same"),  # [inf, 0.2]: falls
                          trend("T4", [0, 1], "not measured", field="stable_again_measured"),  # [inf, null]
                          trend("T5", [2, 3], "falls", relative=-1))
        self.assertEqual(p["T1"], [])
        self.assertEqual(p["T2"], [])
        self.assertIn('is "falls", the claim says "stays the same"', p["T3"][0])
        self.assertEqual(p["T4"], [])
        self.assertTrue(p["T5"])


class Spearman(Folder):
    def test_by_hand(self):
        # x = [1, 2, 2, inf] ranks [1, 2.5, 2.5, 4]; y = [0.5, inf, 0.1, 0.3] ranks [3, 4, 1, 2].
        # Deviations from 2.5: dx = [-1.5, 0, 0, 1.5], dy = [0.5, 1.5, -1.5, -0.5];
        # sum dx dy = -1.5, sum dx^2 = 4.5, sum dy^2 = 5: rho = -1.5 / sqrt(22.5) = -1/sqrt(10)
        # = -0.316228, |rho| in [0.3, 0.7): "moderate negative".
        rho, words = vc.spearman([1, 2, 2, INF], [0.5, INF, 0.1, 0.3])
        self.assertAlmostEqual(rho, -1 / math.sqrt(10), places=12)
        self.assertEqual(words, "moderate negative")
        self.assertEqual(vc.spearman([1, 1, 1], [3, 1, 2]), (0.0, "weak positive"))  # constant
        self.assertEqual(vc.spearman([1, 2, 3], [10, 20, INF])[1], "strong positive")  # rho 1

    def test_claims(self):
        p = self.problems(spearman("S1"),  # |-0.316228 + 0.32| = 0.0038 <= 0.005
                          spearman("S2", value=-0.3, decimals=1),  # 0.0162 <= 0.05
                          spearman("S3", value=-0.31),  # 0.0062 > 0.005
                          spearman("S4", words="weak negative"),
                          spearman("S5", words="moderate positive"))
        self.assertEqual(p["S1"], [])
        self.assertEqual(p["S2"], [])
        self.assertIn("-0.3162", p["S3"][0])
        self.assertTrue(p["S4"] and p["S5"])


class Threshold(Folder):
    def test_claims(self):
        # dt_measured: forward_euler 0.2, backward_euler unbounded, trapezoid unbounded, rk4 0.2183;
        # stable_again_measured: forward_euler never, backward_euler null
        p = self.problems(threshold("H1", [0, 3], "<", 0.25),  # 0.2, 0.2183 < 0.25
                          threshold("H2", [0, 3], ">", 0.21),  # 0.2 is not > 0.21
                          threshold("H3", [0, 1], ">", 0.1, field="stable_again_measured"),  # never, null
                          threshold("H4", [], "<", 0.25),  # empty evidence
                          threshold("H5", [1, 2], ">", 1e300),  # unbounded, unbounded: +infinity
                          threshold("H6", [1, 3], "<", 0.25),  # unbounded is not < 0.25
                          threshold("H7", [0], "<=", 0.2),  # 0.2 <= 0.2
                          threshold("H8", [0], "<", 0.2),  # 0.2 is not < 0.2
                          threshold("H9", [0], ">=", 1e300, field="stable_again_measured"),  # never
                          threshold("H10", [0, 3], "==", 0.25),  # unknown op
                          threshold("H11", [0, 3], "<", "unbounded"))  # limit not a number
        for cid in ("H1", "H5", "H7", "H9"):
            self.assertEqual(p[cid], [], cid)
        self.assertEqual(p["H2"], ["evidence 0 is 0.2, not > 0.21"])
        self.assertEqual(len(p["H3"]), 1, p["H3"])
        self.assertIn("evidence 1 is null", p["H3"][0])
        self.assertIn("empty", p["H4"][0])
        self.assertEqual(p["H6"], ["evidence 0 is inf, not < 0.25"])
        self.assertEqual(p["H8"], ["evidence 0 is 0.2, not < 0.2"])
        self.assertIn('op is "=="', p["H10"][0])
        self.assertIn("limit", p["H11"][0])

    def test_mutation(self):
        # forward_euler's dt_measured in the file becomes 0.3: past the limit 0.25, and no longer
        # the recorded 0.2
        moved = copy.deepcopy(STABILITY)
        moved["thresholds"][0]["dt_measured"] = 0.3
        p = self.problems(threshold("H1", [0, 3], "<", 0.25), stability=moved)["H1"]
        self.assertIn("recorded 0.2, the file holds 0.3", p[0])
        self.assertEqual(p[1], "evidence 0 is 0.3, not < 0.25")
        self.write([threshold("H1", [0, 3], "<", 0.25), trend("T1", [1, 2], "stays unbounded")], moved)
        out = self.run_cli()
        self.assertEqual(out.returncode, 1)
        self.assertTrue(out.stdout.startswith("H1: "), out.stdout)
        self.assertNotIn("T1", out.stdout)
        self.assertIn("claims: 2, hold: 1, do not hold: 1", out.stdout)


class Comparison(Folder):
    def test_claims(self):
        # seconds: rk4 1.0, trapezoid 1.5, backward_euler 1.05, forward_euler null, leapfrog never;
        # spreads: rk4 1.1, trapezoid 1.2, backward_euler 1.02
        bad_index = comparison("C12", "less", 1.3, 0, [1])
        bad_index["rule"]["others"] = [1, 2]  # two evidence values only
        p = self.problems(comparison("C1", "less", 1.3, 0, [1], noise=[0, 2]),  # noise 1.122 < 1.3 = M <= 1.5
                          comparison("C2", "less", 1.2, 0, [1], noise=[0, 1]),  # M = noise 1.32 <= 1.5
                          comparison("C3", "less", 1.01, 0, [2], noise=[0, 2]),  # 1.05 < M = 1.122
                          comparison("C4", "tie", 1.1, 0, [2, 1]),  # 1.05 < 1.1, the first is least
                          comparison("C5", "tie", 1.1, 0, [1, 2]),  # the least is the second
                          comparison("C6", "less", 1.01, 2, [0, 1]),  # a 1.05 is above rk4's 1.0
                          comparison("C7", "less", 1.01, 3, [1]),  # a is null
                          comparison("C8", "less", 1.3, 0, [1, 3]),  # an other is null
                          comparison("C9", "less", 1.3, 0, []),  # B = +infinity
                          comparison("C10", "tie", 1.3, 0, []),  # nothing to tie with
                          comparison("C11", "tie", 1.0, 4, [4]),  # never == never: B == a
                          bad_index,
                          comparison("C13", "more", 1.3, 0, [1]),  # unknown relation
                          comparison("C14", "less", 1.3, 0, [1, 4]))  # never is above 1.5
        for cid in ("C1", "C2", "C4", "C9", "C11", "C14"):
            self.assertEqual(p[cid], [], cid)
        self.assertEqual(len(p["C3"]), 1, p["C3"])
        self.assertIn("1.05 is not >= M a = 1.122", p["C3"][0])
        self.assertEqual(p["C5"], ["tie: the first of others (evidence 1) is 1.5, not the least, 1.05"])
        self.assertEqual(p["C6"][0], "a (evidence 0) is 1.05, above evidence 1 (1.0)")  # and B < M a
        self.assertEqual(p["C7"], ["evidence 0 null (not measured)"])
        self.assertEqual(p["C8"], ["evidence 2 null (not measured)"])
        self.assertIn("tie: others is empty, nothing to tie with", p["C10"])
        self.assertIn("not an index", p["C12"][0])
        self.assertIn('relation is "more"', p["C13"][0])
        # the margin alone would let C3 hold: the noise product decides
        self.assertEqual(self.problems(comparison("C3", "less", 1.01, 0, [2]))["C3"], [])

    def test_mutation(self):
        # trapezoid's run time in the file becomes 1.2: below M a = 1.32, and not the recorded 1.5
        moved = copy.deepcopy(COST)
        moved["cheapest"][1]["seconds"] = 1.2
        p = self.problems(comparison("C2", "less", 1.2, 0, [1], noise=[0, 1]), cost=moved)["C2"]
        self.assertIn("recorded 1.5, the file holds 1.2", p[0])
        self.assertIn("less: the least other 1.2 is not >= M a", p[1])
        self.write([comparison("C2", "less", 1.2, 0, [1], noise=[0, 1]),
                    comparison("C4", "tie", 1.1, 0, [2])], cost=moved)  # reads no trapezoid value
        out = self.run_cli()
        self.assertEqual(out.returncode, 1)
        self.assertTrue(out.stdout.startswith("C2: "), out.stdout)
        self.assertNotIn("C4", out.stdout)
        self.assertIn("claims: 2, hold: 1, do not hold: 1", out.stdout)


class Evidence(Folder):
    def test_pointer(self):
        doc = {"a/b": {"m~n": [10, 20]}, "": 3}
        self.assertEqual(vc.resolve(doc, "/a~1b/m~0n/1"), 20)
        self.assertEqual(vc.resolve(doc, "/"), 3)
        self.assertIs(vc.resolve(doc, ""), doc)
        for bad in ["/a~1b/m~0n/01", "/a~1b/m~0n/2", "/a~2b", "a", "/a~1b/m~0n/-"]:
            self.assertRaises(vc.Fail, vc.resolve, doc, bad)

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
                    threshold("H1", [0, 3], "<", 0.25), comparison("C1", "less", 1.3, 0, [1])])
        out = self.run_cli()
        self.assertEqual((out.returncode, out.stdout), (0, "claims: 5, hold: 5, do not hold: 0\n"))
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


if __name__ == "__main__":
    unittest.main()

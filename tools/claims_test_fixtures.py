"""Fixtures shared by tools/claims_rules_test.py and tools/verify_claims_test.py: made-up data
files, builders of claims over them, and Folder, a test case that writes a small report folder
(data/claims.json and the data files) in a temporary directory and runs verify() or the command
line on it.  Not a test file itself.
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "verify_claims.py")
if HERE not in sys.path:
    sys.path.insert(0, HERE)
import verify_claims as vc  # the files, the claim loop and the command line

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
    "sweep": [  # rows 0..3 at dt 0.5, row 4 at dt 0.1; trapezoid (row 2) has no growth
        {"method": "forward_euler", "dt": 0.5, "stable": False, "growth": 3.2},
        {"method": "backward_euler", "dt": 0.5, "stable": True, "growth": 0.9},
        {"method": "trapezoid", "dt": 0.5, "stable": True},
        {"method": "exact", "dt": 0.5, "stable": True, "growth": 1.0},
        {"method": "forward_euler", "dt": 0.1, "stable": True, "growth": 0.99}],
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
# Each error level: steplab's and a peer's cheapest run (the peer's over steplab's in the comment)
PEERS = {"levels": [  # 0..7
    {"error": 1e-2, "steplab": 2.0, "peer": 5.11},  # 2.555 (in doubles 2.55500000000000016...)
    {"error": 1e-3, "steplab": 1.0, "peer": 2.566},  # 2.566
    {"error": 1e-4, "steplab": 0.5, "peer": 0.434},  # 0.868
    {"error": 1e-5, "steplab": 1, "peer": 9.996},  # 9.996: "10.0" to 3 significant digits
    {"error": 1e-6, "steplab": 10, "peer": 1800},  # 180
    {"error": 1e-7, "steplab": 0.0, "peer": 1.0},  # a zero denominator
    {"error": 1e-8, "steplab": 1.0, "peer": None},  # not measured
    {"error": 1e-9, "steplab": 1.0, "peer": "unbounded"}]}
PF = "cost/peers.json"


def ev(pointer, value, file=SF):
    return {"file": file, "pointer": pointer, "value": value}


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


# Evidence for equality and count: dt_measured of forward_euler 0.2 (0), rk4 0.2183 (1),
# backward_euler unbounded (2), trapezoid unbounded (3); stable_again_measured of forward_euler
# never (4), backward_euler null (5)
EVIDENCE = [(0, "dt_measured"), (3, "dt_measured"), (1, "dt_measured"), (2, "dt_measured"),
            (0, "stable_again_measured"), (1, "stable_again_measured")]


def over_thresholds(cid, kind, rule):
    return {"id": cid, "section": "stability", "sentence": "...", "kind": kind, "rule": rule,
            "evidence": [ev("/thresholds/%d/%s" % (i, f), STABILITY["thresholds"][i][f]) for i, f in EVIDENCE]}


def equality(cid, pairs, relative=0, absolute=0):
    return over_thresholds(cid, "equality", {"pairs": pairs, "relative": relative, "absolute": absolute})


def count(cid, groups, n):
    return over_thresholds(cid, "count", {"groups": groups, "count": n})


def comparison(cid, relation, margin, a, others, noise=()):
    """Evidence: row a's seconds, then each of others' seconds, then each of noise's spreads."""
    rows = [a] + list(others)
    return {"id": cid, "section": "cost", "sentence": "cheapest ...", "kind": "comparison",
            "rule": {"a": 0, "others": list(range(1, len(rows))), "relation": relation, "margin": margin,
                     "noise": list(range(len(rows), len(rows) + len(noise)))},
            "evidence": [ev("/cheapest/%d/seconds" % r, COST["cheapest"][r]["seconds"], "cost.json") for r in rows]
            + [ev("/cheapest/%d/seconds_spread" % r, COST["cheapest"][r]["seconds_spread"], "cost.json")
               for r in noise]}


def ratio(cid, levels, least, greatest=None, digits=None):
    """The peer's over steplab's at each of `levels`: evidence 2k the peer's value at levels[k],
    2k + 1 steplab's, ratio k evidence 2k over 2k + 1; digits {"decimals": 2} unless given."""
    return {"id": cid, "section": "cost", "sentence": "the peer takes 0.87 to 2.57 times as long", "kind": "ratio",
            "rule": {"ratios": [{"over": [2 * k], "under": [2 * k + 1]} for k in range(len(levels))],
                     "least": least, "greatest": least if greatest is None else greatest,
                     "digits": {"decimals": 2} if digits is None else digits},
            "evidence": [ev("/levels/%d/%s" % (i, who), PEERS["levels"][i][who], PF) for i in levels
                         for who in ("peer", "steplab")]}


# Groups of a `count` over EVIDENCE: BELOW, SAME and LESS hold, ABOVE does not, NULLS read a null
BELOW = {"kind": "threshold", "rule": {"op": "<", "limit": 0.25, "items": [0]}}  # holds
SAME = {"kind": "equality", "rule": {"pairs": [[2, 3]], "relative": 0, "absolute": 0}}  # holds
ABOVE = {"kind": "threshold", "rule": {"op": ">", "limit": 0.3, "items": [1]}}  # does not hold
LESS = {"kind": "comparison", "rule": {"a": 0, "others": [1], "relation": "less", "margin": 1.0,
                                       "noise": []}}  # holds: 0.2 < 0.2183
NULLS = [{"kind": "threshold", "rule": {"op": "<", "limit": 1, "items": [5]}},
         {"kind": "comparison", "rule": {"a": 5, "others": [0], "relation": "less", "margin": 1.0,
                                         "noise": []}},
         {"kind": "equality", "rule": {"pairs": [[0, 5]], "relative": 1, "absolute": 1}}]


class Folder(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, claims, stability=STABILITY, raw=None, cost=COST, peers=PEERS, **top):
        for folder in ("stability", "cost"):
            os.makedirs(os.path.join(self.dir, "data", folder), exist_ok=True)
        for name, doc in [(SF, stability), ("stats.json", STATS), ("cost.json", cost), (PF, peers)]:
            with open(os.path.join(self.dir, "data", name), "w") as f:
                json.dump(doc, f)
        with open(os.path.join(self.dir, "data", "claims.json"), "w") as f:
            f.write(raw if raw is not None else
                    json.dumps(dict({"schema": "steplab.claims/1", "methods": METHODS, "claims": claims},
                                    **top)))

    def problems(self, *claims, stability=STABILITY, cost=COST, peers=PEERS):
        self.write(list(claims), stability, cost=cost, peers=peers)
        return dict(vc.verify(self.dir))

    def run_cli(self):
        return subprocess.run([sys.executable, SCRIPT, self.dir], capture_output=True, text=True)

    def cli_names_only(self, claims, failing, **files):
        """The command line on `claims` (and `files`, as write takes them) exits 1, names
        `failing` first and no other claim, and counts just that one as not holding."""
        self.write(claims, **files)
        out = self.run_cli()
        self.assertEqual(out.returncode, 1)
        self.assertTrue(out.stdout.startswith(failing + ": "), out.stdout)
        for c in claims:
            if c["id"] != failing:
                self.assertNotIn(c["id"], out.stdout)
        self.assertIn("claims: %d, hold: %d, do not hold: 1" % (len(claims), len(claims) - 1), out.stdout)

"""Tests of tools/claims_extremes.py: python3 tools/claims_extremes_test.py

`extreme` (the least or the greatest of a list, as printed) and `mismatch` (the cells two arrays
disagree in) on claims over made-up data files in a small report folder
(claims_test_fixtures.Folder), each with a planted falsehood the verifier must name.
"""
import copy
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
if HERE not in sys.path:
    sys.path.insert(0, HERE)
from claims_test_fixtures import COST, SF, STABILITY, Folder, ev  # noqa: E402


def extreme(cid, which, a, others, printed=None, digits=None):
    """Evidence: row a's seconds in cost.json, then each of others' (rk4 1.0, trapezoid 1.5,
    backward_euler 1.05, forward_euler null, leapfrog never)."""
    rule = {"a": 0, "others": list(range(1, len(others) + 1)), "which": which}
    if printed is not None:
        rule.update(printed=printed, digits=digits or {"significant": 3})
    return {"id": cid, "section": "cost", "sentence": "the fastest ...", "kind": "extreme", "rule": rule,
            "evidence": [ev("/cheapest/%d/seconds" % r, COST["cheapest"][r]["seconds"], "cost.json") for r in [a] + others]}


# Two 2 x 3 maps of verdicts: measured and predicted; they differ in one cell ([1][2])
MAPS = dict(STABILITY, map={"stable": {"rk4": [[True, True, False], [True, False, False]]},
                            "predicted": {"rk4": [[True, True, False], [True, False, True]]},
                            "flat": {"rk4": [True, True, False, True, False, False]}})


def mismatch(cid, count, second="predicted"):
    return {"id": cid, "section": "stability", "sentence": "1 of the 6 cells disagrees", "kind": "mismatch",
            "rule": {"pairs": [[0, 1]], "count": count},
            "evidence": [ev("/map/stable/rk4", MAPS["map"]["stable"]["rk4"]),
                         ev("/map/%s/rk4" % second, MAPS["map"][second]["rk4"])]}


class Extreme(Folder):
    def test_claims(self):
        p = self.problems(extreme("E1", "least", 0, [1, 2]),  # 1.0 of 1.0, 1.5, 1.05
                          extreme("E2", "greatest", 1, [0, 2]),  # 1.5
                          extreme("E3", "least", 2, [0, 1]),  # 1.05 is not the least
                          extreme("E4", "greatest", 4, [0, 1]),  # never: +infinity, the greatest
                          extreme("E5", "least", 0, [3]),  # an other is null
                          extreme("E6", "least", 0, [0]),  # a tie with itself: still the least
                          extreme("E7", "fastest", 0, [1]),  # unknown which
                          extreme("E8", "greatest", 1, [0], printed="1.50", digits={"decimals": 2}),
                          extreme("E9", "greatest", 2, [0], printed="1.1", digits={"significant": 2}),  # 1.05 is "1.0" or "1.1"
                          extreme("E10", "greatest", 1, [0], printed="1.6", digits={"significant": 2}),
                          extreme("E11", "greatest", 4, [0], printed="1e9"))  # +infinity is not printed
        for cid in ("E1", "E2", "E4", "E6", "E8", "E9"):
            self.assertEqual(p[cid], [], cid)
        self.assertEqual(p["E3"], ["a 0 is 1.05, not the least: 1 is 1.0"])
        self.assertEqual(p["E5"], ["evidence 1 null (not measured)"])
        self.assertIn('which is "fastest"', p["E7"][0])
        self.assertEqual(p["E10"], ['a 0 1.5 is not "1.6" to 2 significant digits'])
        self.assertEqual(p["E11"], ["a 0 is inf, not a finite number to print"])

    def test_differences(self):
        # items [i, j]: evidence i minus evidence j; seconds 1.0, 1.5, 1.05 (rows 0, 1, 2)
        d = extreme("D1", "greatest", 0, [1, 2])
        d["rule"].update(a=[1, 0], others=[[2, 0], [1, 2]])  # 0.5 against 0.05 and 0.45
        self.assertEqual(self.problems(d)["D1"], [])
        d["rule"]["a"] = [2, 0]  # 0.05 is not the greatest
        self.assertEqual(self.problems(d)["D1"][0], "a [2, 0] is 0.050000000000000044, not the greatest: [1, 2] is 0.44999999999999996")
        d["rule"]["a"] = [2, 7]  # no evidence 7
        self.assertIn("not an evidence index or a pair", self.problems(d)["D1"][0])

    def test_mutation(self):
        # backward_euler's run time in the file becomes 0.9: rk4 is no longer the least
        moved = copy.deepcopy(COST)
        moved["cheapest"][2]["seconds"] = 0.9
        claims = [extreme("E1", "least", 0, [1, 2]), extreme("E2", "greatest", 1, [0])]
        p = self.problems(*claims, cost=moved)["E1"]
        self.assertIn("recorded 1.05, the file holds 0.9", p[0])
        self.assertIn("not the least: 2 is 0.9", p[1])
        self.cli_names_only(claims, "E1", cost=moved)  # E2 reads no backward_euler value


class Mismatch(Folder):
    def test_claims(self):
        p = self.problems(mismatch("M1", 1), mismatch("M2", 0), mismatch("M3", 0, second="stable"),
                          mismatch("M4", 0, second="flat"), stability=MAPS)
        self.assertEqual(p["M1"], [])
        self.assertEqual(p["M2"], ["1 cells differ, the claim says 0"])
        self.assertEqual(p["M3"], [])  # a map against itself
        self.assertEqual(p["M4"], ["pair [0, 1]: not two arrays of the same shape"])

    def test_mutation(self):
        # one more cell of the measured map flips: 2 differ, the claim says 1
        moved = copy.deepcopy(MAPS)
        moved["map"]["stable"]["rk4"][0][0] = False
        p = self.problems(mismatch("M1", 1), stability=moved)["M1"]
        self.assertIn("recorded [[true, true, false], [true, false, false]]", p[0])
        self.assertEqual(p[-1], "2 cells differ, the claim says 1")
        self.cli_names_only([mismatch("M1", 1), extreme("E1", "least", 0, [1])], "M1", stability=moved)

    def test_a_large_map_names_its_cell(self):
        # a 64 x 64 map: the message names the cell that moved, not the whole array
        big = [[(r + c) % 3 == 0 for c in range(64)] for r in range(64)]
        maps = dict(STABILITY, map={"stable": {"rk4": big}, "predicted": {"rk4": copy.deepcopy(big)}})
        claim = {"id": "M5", "section": "stability", "sentence": "0 of the 4096 cells disagree", "kind": "mismatch",
                 "rule": {"pairs": [[0, 1]], "count": 0},
                 "evidence": [ev("/map/stable/rk4", big), ev("/map/predicted/rk4", big)]}
        moved = copy.deepcopy(maps)
        moved["map"]["stable"]["rk4"][10][20] = not big[10][20]
        self.assertEqual(self.problems(claim, stability=maps)["M5"], [])
        self.assertEqual(self.problems(claim, stability=moved)["M5"],
                         ["evidence 0 (stability/stability.json /map/stable/rk4): recorded true at /10/20, the file holds false",
                          "1 cells differ, the claim says 0"])


if __name__ == "__main__":
    assert SF == "stability/stability.json"
    unittest.main()

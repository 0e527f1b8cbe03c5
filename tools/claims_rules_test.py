"""Tests of tools/claims_rules.py: python3 tools/claims_rules_test.py

The words of a trend, Spearman's rho and ratios as printed by hand, and each kind's rule check
(trend, statistic, threshold, comparison, equality, ratio, count) on claims over made-up data
files, run through a small report folder (claims_test_fixtures.Folder).  The row-test language
(tools/claims_rows_test.py) is run here too.  Membership, evidence, pointers, the claim loop and
the command line: tools/verify_claims_test.py.
"""
import copy
import math
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
if HERE not in sys.path:
    sys.path.insert(0, HERE)
import claims_rules as cr  # the rules, pure functions over values
from claims_rows_test import And, Tests  # noqa: F401  the row-test language's tests, run here too
from claims_test_fixtures import (ABOVE, BELOW, COST, LESS, NULLS, SAME, STABILITY, Folder, comparison, count,
                                  equality, ratio, spearman, threshold, trend)
from fractions import Fraction
INF = math.inf


class Trend(Folder):
    def test_words(self):
        self.assertEqual(cr.trend_of([INF, INF], 1e-3), "stays unbounded")
        self.assertEqual(cr.trend_of([INF, 0.2183], 1e-3), "falls")  # inf is never a number
        self.assertEqual(cr.trend_of([0.2183, INF], 1.0), "rises")
        # |0.5 - 0.50001| = 1e-5 <= 1e-3 * 0.50001
        self.assertEqual(cr.trend_of([0.5, 0.50001], 1e-3), "stays the same")
        self.assertEqual(cr.trend_of([0.5, 0.50001], 1e-6), "rises")  # 1e-5 > 5.0001e-7
        self.assertEqual(cr.trend_of([0.1, 0.2, 0.15], 1e-3), "does not move one way")
        self.assertEqual(cr.trend_of([1.0, None], 1e-3), "not measured")
        self.assertEqual(cr.trend_of([INF, None], 1e-3), "not measured")

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
        rho, words = cr.spearman([1, 2, 2, INF], [0.5, INF, 0.1, 0.3])
        self.assertAlmostEqual(rho, -1 / math.sqrt(10), places=12)
        self.assertEqual(words, "moderate negative")
        self.assertEqual(cr.spearman([1, 1, 1], [3, 1, 2]), (0.0, "weak positive"))  # constant
        self.assertEqual(cr.spearman([1, 2, 3], [10, 20, INF])[1], "strong positive")  # rho 1

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
                          threshold("H11", [0, 3], "<", "unbounded"),  # limit not a number
                          dict(threshold("H12", [0, 1, 3], "<", 0.25), rule={"op": "<", "limit": 0.25, "items": [0, 2]}),
                          dict(threshold("H13", [0, 1, 3], "<", 0.25), rule={"op": "<", "limit": 0.25, "items": [2, 1]}),
                          dict(threshold("H14", [0, 1, 3], "<", 0.25), rule={"op": "<", "limit": 0.25, "items": []}),
                          dict(threshold("H15", [0, 1, 3], "<", 0.25), rule={"op": "<", "limit": 0.25, "items": [3]}),
                          dict(threshold("H16", [0, 1, 3], "<", 0.25), rule={"op": "<", "limit": 0.25, "items": 0}))
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
        # items: 0.2 and 0.2183 (evidence 0, 2) hold; evidence 1 (unbounded) is left out, or not
        self.assertEqual(p["H12"], [])
        self.assertEqual(p["H13"], ["evidence 1 is inf, not < 0.25"])
        self.assertEqual(p["H14"], ["the items are empty"])
        self.assertIn("items [3] is not a list of indices", p["H15"][0])
        self.assertIn("items 0 is not a list of indices", p["H16"][0])

    def test_mutation(self):
        # forward_euler's dt_measured in the file becomes 0.3: past the limit 0.25, and no longer
        # the recorded 0.2
        moved = copy.deepcopy(STABILITY)
        moved["thresholds"][0]["dt_measured"] = 0.3
        p = self.problems(threshold("H1", [0, 3], "<", 0.25), stability=moved)["H1"]
        self.assertIn("recorded 0.2, the file holds 0.3", p[0])
        self.assertEqual(p[1], "evidence 0 is 0.3, not < 0.25")
        self.cli_names_only([threshold("H1", [0, 3], "<", 0.25), trend("T1", [1, 2], "stays unbounded")], "H1", stability=moved)


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
        self.cli_names_only([comparison("C2", "less", 1.2, 0, [1], noise=[0, 1]),
                             comparison("C4", "tie", 1.1, 0, [2])], "C2", cost=moved)  # C4 reads no trapezoid value


class Equality(Folder):
    def test_claims(self):
        # evidence: 0.2, 0.2183, unbounded, unbounded, never, null
        p = self.problems(equality("Q1", [[2, 3]]),  # inf == inf
                          equality("Q2", [[2, 4], [4, 3]]),  # "unbounded" and "never" are both +infinity
                          equality("Q3", [[0, 2]], relative=1e9, absolute=1e300),  # inf is no number
                          equality("Q4", [[0, 1]], relative=0.1),  # 0.0183 <= 0.1 x 0.2183
                          equality("Q5", [[0, 1]], relative=0.05),  # 0.0183 > 0.05 x 0.2183
                          equality("Q6", [[1, 0]], absolute=0.02),  # 0.0183 <= 0.02
                          equality("Q7", [[0, 1]], relative=0.05, absolute=0.01),  # > max(0.01, 0.0109)
                          equality("Q8", [[0, 1]], relative=0.05, absolute=0.019),  # max is absolute
                          equality("Q9", [[0, 1]], relative=0.09, absolute=0.001),  # max is relative
                          equality("Q10", [[0, 5]], relative=1, absolute=1),  # null
                          equality("Q11", [[5, 5]], relative=1, absolute=1),  # null == null fails too
                          equality("Q12", []),  # no pairs
                          equality("Q13", [[0, 6]]),  # not an index
                          equality("Q14", [[0, 0]], relative=-1),
                          equality("Q15", [[2, 3], [0, 1]]))  # one pair of two is not equal
        for cid in ("Q1", "Q2", "Q4", "Q6", "Q8", "Q9"):
            self.assertEqual(p[cid], [], cid)
        self.assertEqual(p["Q3"], ["pair [0, 2]: 0.2 and inf, +infinity equals no number"])
        self.assertEqual(len(p["Q5"]), 1, p["Q5"])
        self.assertIn("pair [0, 1]: 0.2 and 0.2183 differ by 0.0183", p["Q5"][0])
        self.assertIn("above max(0, 0.05 x 0.2183)", p["Q5"][0])
        self.assertEqual(len(p["Q7"]), 1, p["Q7"])
        self.assertEqual(p["Q10"], ["pair [0, 5]: a null value (not measured)"])
        self.assertEqual(p["Q11"], ["pair [5, 5]: a null value (not measured)"])
        self.assertEqual(p["Q12"], ["pairs is empty"])
        self.assertIn("is not a list of [i, j] indices into the 6 evidence values", p["Q13"][0])
        self.assertIn("relative -1", p["Q14"][0])
        self.assertEqual(len(p["Q15"]), 1, p["Q15"])
        self.assertIn("pair [0, 1]", p["Q15"][0])


def one(value, printed, digits=None):
    """check_ratio on a single ratio, `value` over an empty product, printed as least and greatest."""
    rule = {"ratios": [{"over": [0], "under": []}], "least": printed, "greatest": printed,
            "digits": {"decimals": 2} if digits is None else digits}
    return cr.check_ratio(rule, [value])


def several(values, ratios, least, greatest, digits=None):
    return cr.check_ratio({"ratios": [{"over": o, "under": u} for o, u in ratios], "least": least,
                           "greatest": greatest, "digits": {"decimals": 2} if digits is None else digits}, values)


class Ratio(Folder):
    SIG3 = {"significant": 3}

    def test_half_a_unit(self):
        # 2.555 is 2.55500000000000016... in binary: 0.00500000000000016 from "2.55", above half a
        # unit (0.005) by 1.6e-16, within the slack 1e-9 x 2.555; 0.00499999999999984 from "2.56"
        self.assertGreater(abs(Fraction(2.555) - Fraction("2.55")), Fraction(5, 1000))
        self.assertEqual(one(2.555, "2.56"), [])
        self.assertEqual(one(2.555, "2.55"), [])
        # 2.565 is 2.56499999999999995...: "2.57" by the slack, "2.56" within half a unit
        self.assertGreater(abs(Fraction(2.565) - Fraction("2.57")), Fraction(5, 1000))
        self.assertEqual(one(2.565, "2.57"), [])
        self.assertEqual(one(2.565, "2.56"), [])
        self.assertEqual(one(2.566, "2.57"), [])
        p = one(2.566, "2.56")  # off by 0.006
        self.assertEqual(len(p), 2, p)  # least and greatest, the same string
        self.assertIn('the least ratio 2.566 (ratio 0) is not "2.56" to 2 decimals: off by 0.006', p[0])
        self.assertIn("the greatest ratio 2.566", p[1])
        self.assertTrue(one(2.55499, "2.56"))  # 0.00501: beyond the slack (2.6e-9)
        self.assertTrue(one(2.5449, "2.55"))
        self.assertTrue(one(2.555 + 1e-8, "2.55"))  # 0.00500001: beyond it too
        self.assertEqual(one(3.5, "3.5", {"decimals": 1}), [])
        self.assertEqual(one(180.4, "180", {"decimals": 0}), [])
        self.assertTrue(one(180.6, "180", {"decimals": 0}))
        self.assertEqual(one(-0.8684, "-0.868", {"decimals": 3}), [])  # a negative over product

    def test_significant_digits(self):
        # the unit is that of the printed L: 0.5 10^(e - s + 1), e = floor(log10 |L|)
        self.assertEqual(one(9.996, "10.0", self.SIG3), [])  # e = 1: 0.05, across the decade
        self.assertEqual(one(9.994, "9.99", self.SIG3), [])  # e = 0: 0.005
        self.assertTrue(one(9.996, "9.99", self.SIG3))  # 0.006 > 0.005
        self.assertTrue(one(9.94, "10.0", self.SIG3))  # 0.06 > 0.05
        self.assertEqual(one(0.99951, "1.00", self.SIG3), [])
        self.assertEqual(one(0.868, "0.868", self.SIG3), [])  # e = -1: 0.0005
        self.assertTrue(one(0.8686, "0.868", self.SIG3))
        self.assertEqual(one(1234.9, "1.23e+03", self.SIG3), [])  # e = 3: 5
        self.assertTrue(one(1235.1, "1.23e+03", self.SIG3))
        self.assertIn("to 3 significant digits", one(1235.1, "1.23e+03", self.SIG3)[0])
        self.assertEqual(one(180.4, "180", self.SIG3), [])  # e = 2: 0.5
        self.assertTrue(one(184, "180", self.SIG3))
        self.assertEqual(one(184, "180", {"significant": 2}), [])  # 5
        self.assertEqual(one(0.0001234, "1.23e-4", self.SIG3), [])  # e = -4: 5e-7
        # a printed "0" to significant digits: exactly 0; to decimals, half a unit as ever
        self.assertEqual(one(0.0, "0", self.SIG3), [])
        self.assertEqual(one(0, "0.00", self.SIG3), [])
        p = one(1e-12, "0", self.SIG3)
        self.assertEqual(len(p), 2, p)
        self.assertIn("it is not 0", p[0])
        self.assertEqual(one(0.004, "0.00"), [])
        self.assertTrue(one(0.006, "0.00"))

    def test_products_and_range(self):
        values = [3.0, 2.0, 4.0, 1.5, 0.25]
        self.assertEqual(several(values, [([0, 1], [2, 3])], "1.00", "1.00"), [])  # 6 / 6
        self.assertEqual(several(values, [([], [2])], "0.25", "0.25"), [])  # empty over: 1 / 4
        self.assertEqual(several(values, [([], [])], "1.00", "1.00"), [])  # 1 / 1
        self.assertEqual(several(values, [([2], [4, 4])], "64.00", "64.00"), [])
        # ratios 1.5, 0.75, 6: least 0.75 (ratio 1), greatest 6 (ratio 2)
        three = [([0], [1]), ([3], [1]), ([0, 1], [])]
        self.assertEqual(several(values, three, "0.75", "6.00"), [])
        self.assertEqual(several(values, three, "0.8", "6", {"decimals": 1}), [])  # 0.05 from 0.75
        self.assertEqual(several(values, three, "0.75", "1.50"),
                         ['the greatest ratio 6 (ratio 2) is not "1.50" to 2 decimals: off by 4.5, above 0.005 + 6e-09'])
        p = several(values, three, "1.50", "6.00")  # least misprinted as another ratio
        self.assertEqual(len(p), 1, p)
        self.assertIn('the least ratio 0.75 (ratio 1) is not "1.50"', p[0])
        self.assertEqual(len(several(values, three, "0.76", "6.01")), 2)

    def test_values_it_cannot_divide(self):
        values = [2.0, 0.0, None, "unbounded", "never", -1.0, 0, True]
        self.assertEqual(several(values, [([0], [1])], "1.00", "1.00"),
                         ["ratio 0: the under product 0.0 is not above 0"])
        self.assertEqual(several(values, [([0], [6])], "1.00", "1.00"),
                         ["ratio 0: the under product 0.0 is not above 0"])  # an integer 0
        self.assertEqual(several(values, [([0], [0]), ([0], [5, 0])], "-1.00", "1.00"),
                         ["ratio 1: the under product -2.0 is not above 0"])
        self.assertEqual(several(values, [([0], [5, 5])], "2.00", "2.00"), [])  # (-1)(-1) > 0
        self.assertEqual(several(values, [([2], [0])], "1.00", "1.00"),
                         ["evidence 2 is null (not measured), not a finite number"])
        self.assertEqual(several(values, [([3], [0]), ([0], [4])], "1.00", "1.00"),
                         ['evidence 3 is "unbounded", not a finite number', 'evidence 4 is "never", not a finite number'])
        self.assertEqual(several(values, [([0], [7])], "2.00", "2.00"),
                         ["evidence 7 is true, not a finite number"])  # true is not 1
        self.assertEqual(several(values, [([0], [])], "2.00", "2.00"), [])  # the values not read
        self.assertEqual(several(values, [], "1.00", "1.00"), ["ratios is empty"])

    def test_malformed(self):
        for digits in [{"decimals": 2, "significant": 3}, {}, {"decimals": -1}, {"significant": 0},
                       {"decimals": 2.0}, {"decimals": True}, {"decimals": "2"}, {"digits": 2}, "2", 2,
                       [{"decimals": 2}], {"significant": None}]:
            self.assertRaises(cr.Fail, one, 2.0, "2.00", digits)
        for printed in [2.0, None, "", "2,00", " 2.00", "2.00 ", "nan", "inf", "Infinity", "2_0", "1/2",
                        "e3", ".", "+2", "2.0.0", "0x2"]:
            self.assertRaises(cr.Fail, one, 2.0, printed)
        for ratios in [{"over": [0], "under": []}, [{"over": [0]}], [{"over": 0, "under": []}],
                       [{"over": [1], "under": []}], [{"over": [True], "under": []}], [[[0], []]]]:
            self.assertRaises(cr.Fail, cr.check_ratio, {"ratios": ratios, "least": "2.00", "greatest": "2.00",
                                                        "digits": {"decimals": 2}}, [2.0])

    def test_claims(self):
        # the peer's over steplab's, PEERS: 2.555, 2.566, 0.868, 9.996, 180, 1 / 0, null, unbounded
        sig = {"significant": 3}
        p = self.problems(ratio("R1", [0], "2.56"), ratio("R2", [0], "2.55"), ratio("R3", [1], "2.56"),
                          ratio("R4", [0, 1, 2], "0.87", "2.57"), ratio("R5", [0, 1, 2], "0.86", "2.57"),
                          ratio("R6", [0, 1, 2], "0.87", "2.56"), ratio("R7", [3], "10.0", digits=sig),
                          ratio("R8", [2, 3, 4], "0.868", "180", sig), ratio("R9", [4, 5], "180"),
                          ratio("R10", [6, 0], "2.56"), ratio("R11", [7], "2.56"), ratio("R12", [], "1.00"),
                          ratio("R13", [0], "2.56", digits={"decimals": 2, "significant": 3}),
                          ratio("R14", [0], "2.56", digits={}))
        for cid in ("R1", "R2", "R4", "R7", "R8"):
            self.assertEqual(p[cid], [], cid)
        self.assertEqual(len(p["R3"]), 2, p["R3"])
        self.assertIn('the least ratio 2.566 (ratio 0) is not "2.56"', p["R3"][0])
        self.assertEqual(len(p["R5"]), 1, p["R5"])
        self.assertIn('the least ratio 0.868 (ratio 2) is not "0.86"', p["R5"][0])
        self.assertEqual(len(p["R6"]), 1, p["R6"])
        self.assertIn('the greatest ratio 2.566 (ratio 1) is not "2.56"', p["R6"][0])
        self.assertEqual(p["R9"], ["ratio 1: the under product 0.0 is not above 0"])
        self.assertEqual(p["R10"], ["evidence 0 is null (not measured), not a finite number"])
        self.assertEqual(p["R11"], ['evidence 0 is "unbounded", not a finite number'])
        self.assertEqual(p["R12"], ["ratios is empty"])
        for cid in ("R13", "R14"):
            self.assertEqual(len(p[cid]), 1, p[cid])
            self.assertIn("digits is ", p[cid][0])


class Count(Folder):
    # evidence: 0.2, 0.2183, unbounded, unbounded, never, null; the groups BELOW, SAME, ABOVE,
    # LESS and NULLS: claims_test_fixtures.py

    def test_claims(self):
        groups = [BELOW, SAME, ABOVE, LESS]
        p = self.problems(count("N1", groups, 3), count("N2", groups, 2), count("N3", groups, 4),
                          count("N4", [], 0), count("N5", groups[2:3], 0), count("N6", groups, -1))
        self.assertEqual(p["N1"], [])
        self.assertEqual(p["N2"], ["3 of the 4 groups hold ([0, 1, 3]), the claim says 2"])
        self.assertEqual(p["N3"], ["3 of the 4 groups hold ([0, 1, 3]), the claim says 4"])
        self.assertEqual(p["N4"], [])
        self.assertEqual(p["N5"], [])
        self.assertIn("count -1", p["N6"][0])

    def test_null_groups_do_not_hold(self):
        p = self.problems(count("N1", [BELOW] + NULLS, 1), count("N2", [BELOW] + NULLS, 2),
                          count("N3", NULLS, 0))
        self.assertEqual(p["N1"], [])
        self.assertEqual(p["N2"], ["1 of the 4 groups hold ([0]), the claim says 2"])
        self.assertEqual(p["N3"], [])

    def test_malformed_group_fails_the_claim(self):
        bad = [({"kind": "trend", "rule": {"along": ["a"], "relative": 0, "trend": "rises"}}, "not an object of kind"),
               ({"kind": "count", "rule": {"groups": [], "count": 0}}, "not an object of kind"),
               ({"kind": "threshold", "rule": {"op": "==", "limit": 1}}, 'op is "=="'),
               ({"kind": "threshold", "rule": {"op": "<", "limit": 1, "items": [9]}}, "items [9]"),
               ({"kind": "equality", "rule": {"pairs": [[0, 1]]}}, "rule lacks one of"),
               ({"kind": "comparison"}, "rule lacks one of"),
               ("threshold", "not an object of kind")]
        for group, why in bad:
            # the count would match if the bad group counted as not holding
            p = self.problems(count("N1", [BELOW, group], 1))["N1"]
            self.assertEqual(len(p), 1, (group, p))
            self.assertTrue(p[0].startswith("group 1: "), p)
            self.assertIn(why, p[0])

    def test_mutation(self):
        # forward_euler's dt_measured becomes 0.3: BELOW and LESS no longer hold
        moved = copy.deepcopy(STABILITY)
        moved["thresholds"][0]["dt_measured"] = 0.3
        p = self.problems(count("N1", [BELOW, SAME, ABOVE, LESS], 3), stability=moved)["N1"]
        self.assertIn("recorded 0.2, the file holds 0.3", p[0])
        self.assertEqual(p[1], "1 of the 4 groups hold ([1]), the claim says 3")


if __name__ == "__main__":
    unittest.main()

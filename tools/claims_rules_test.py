"""Tests of tools/claims_rules.py: python3 tools/claims_rules_test.py

The row-test language on one row, the words of a trend and Spearman's rho by hand, and each kind's
rule check (trend, statistic, threshold, comparison, equality, count) on claims over made-up data
files, run through a small report folder (claims_test_fixtures.Folder).  Membership, evidence,
pointers, the claim loop and the command line: tools/verify_claims_test.py.
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
from claims_test_fixtures import (ABOVE, BELOW, COST, LESS, NULLS, SAME, STABILITY, Folder, comparison, count,
                                  equality, spearman, threshold, trend)
INF = math.inf


class Tests(unittest.TestCase):
    """The test language on one row."""
    ROW = {"stable": True, "n": 1, "dt": "unbounded", "again": "never", "m": None, "name": "rk4",
           "ci": [0.5, 0.75], "a/b": 2}

    def check(self, test):
        cr.test_pointers(test)  # the form is accepted
        return cr.holds(test, self.ROW)

    def test_equals(self):
        f = lambda p, op, v: self.check({"field": p, "op": op, "value": v})
        self.assertIs(f("/stable", "==", True), True)
        self.assertIs(f("/n", "==", True), False)  # true is not 1
        self.assertIs(f("/n", "==", 1.0), True)  # numbers by value
        self.assertIs(f("/dt", "==", "unbounded"), True)  # raw JSON
        self.assertIs(f("/m", "==", None), True)
        self.assertIs(f("/ci", "==", [0.5, 0.75]), True)
        self.assertIs(f("/a~1b", "==", 2), True)
        self.assertIs(f("/missing", "==", None), False)  # finds nothing
        self.assertIs(f("/stable", "!=", False), True)
        self.assertIs(f("/stable", "!=", True), False)
        self.assertIs(f("/n", "!=", True), True)
        self.assertIs(f("/missing", "!=", 1), False)  # "!=" too
        self.assertIs(f("/ci/2", "!=", 1), False)

    def test_order(self):
        f = lambda p, op, v: self.check({"field": p, "op": op, "value": v})
        self.assertIs(f("/n", "<", 2), True)
        self.assertIs(f("/n", "<", 1), False)
        self.assertIs(f("/n", "<=", 1), True)
        self.assertIs(f("/ci/1", ">=", 0.75), True)
        self.assertIs(f("/dt", "<", 1e300), False)  # "unbounded" is +infinity
        self.assertIs(f("/dt", ">", 1e300), True)
        self.assertIs(f("/again", ">", 1e300), True)  # "never" too
        self.assertIs(f("/dt", ">=", "never"), True)
        self.assertIs(f("/dt", "<", "never"), False)
        self.assertIs(f("/n", "<", "unbounded"), True)
        self.assertIs(f("/m", "<", 5), False)  # null
        self.assertIs(f("/m", ">", 5), False)
        self.assertIs(f("/n", "<", None), False)
        self.assertIs(f("/stable", "<", 5), False)  # not a number (true is not 1)
        self.assertIs(f("/name", ">", 0), False)
        self.assertIs(f("/missing", "<", 5), False)
        self.assertIs(f("/ci/9", ">", 0), False)

    def test_difference(self):
        f = lambda ps, op, v: self.check({"difference": ps, "op": op, "value": v})
        self.assertIs(f(["/ci/0", "/ci/1"], "<=", 0.25), True)  # |0.5 - 0.75| = 0.25 exactly
        self.assertIs(f(["/ci/1", "/ci/0"], "<", 0.25), False)
        self.assertIs(f(["/ci/1", "/ci/0"], ">", 0.2), True)
        self.assertIs(f(["/ci/0", "/n"], ">=", 0.5), True)
        self.assertIs(f(["/n", "/dt"], ">", 0), False)  # +infinity
        self.assertIs(f(["/dt", "/dt"], "<", 1), False)
        self.assertIs(f(["/n", "/m"], "<", 5), False)  # null
        self.assertIs(f(["/n", "/name"], "<", 5), False)  # not a number
        self.assertIs(f(["/n", "/missing"], "<", 5), False)
        self.assertIs(f(["/ci/0", "/ci/1"], "<", "unbounded"), True)
        self.assertRaises(cr.Fail, cr.test_pointers, {"difference": ["/n", "/n"], "op": "==", "value": 0})
        self.assertRaises(cr.Fail, cr.test_pointers, {"difference": "/n", "op": "<", "value": 0})

    def test_scaled(self):
        # x1 op c x2: ci = [0.5, 0.75], n 1, dt "unbounded", again "never", m null, name "rk4"
        f = lambda ps, op, c: self.check({"scaled": ps, "op": op, "times": c})
        self.assertIs(f(["/ci/0", "/ci/1"], "<", 1), True)  # 0.5 < 0.75
        self.assertIs(f(["/ci/1", "/ci/0"], "<=", 1.5), True)  # 0.75 <= 1.5 x 0.5, exactly
        self.assertIs(f(["/ci/1", "/ci/0"], "<", 1.5), False)
        self.assertIs(f(["/ci/1", "/ci/0"], ">", 1.4), True)  # 0.75 > 0.7
        self.assertIs(f(["/ci/1", "/ci/0"], ">=", 2), False)  # 0.75 < 1
        self.assertIs(f(["/n", "/ci/0"], ">", -1), True)  # 1 > -0.5: c may be negative
        self.assertIs(f(["/ci/0", "/n"], ">=", 0.5), True)  # an integer x2
        self.assertIs(f(["/dt", "/n"], ">", 1e300), True)  # "unbounded" is +infinity
        self.assertIs(f(["/dt", "/n"], "<", 1e300), False)
        self.assertIs(f(["/n", "/dt"], "<", 1e-300), True)  # 1 < 1e-300 x +infinity
        self.assertIs(f(["/n", "/again"], ">", 1e-300), False)  # "never" too
        self.assertIs(f(["/dt", "/again"], ">=", 1), True)  # +infinity >= +infinity
        self.assertIs(f(["/dt", "/again"], "<", 2), False)
        self.assertIs(f(["/n", "/dt"], "<", 0), False)  # 0 x +infinity is no number
        self.assertIs(f(["/n", "/dt"], ">=", 0), False)
        self.assertIs(f(["/n", "/m"], "<", 2), False)  # null
        self.assertIs(f(["/m", "/n"], "<", 2), False)
        self.assertIs(f(["/n", "/name"], "<", 2), False)  # not a number
        self.assertIs(f(["/stable", "/n"], "<", 2), False)  # true is not 1
        self.assertIs(f(["/ci", "/n"], "<", 2), False)  # an array is not a number
        self.assertIs(f(["/n", "/missing"], "<", 2), False)  # finds nothing
        self.assertIs(f(["/ci/2", "/n"], ">", 0), False)
        self.assertIs(self.check({"not": {"scaled": ["/n", "/missing"], "op": "<", "times": 2}}), True)
        self.assertEqual(cr.test_pointers({"scaled": ["/a", "/b/0"], "op": "<", "times": 2}), ["/a", "/b/0"])
        for bad in [{"scaled": ["/n", "/n"], "op": "==", "times": 1},  # an order only
                    {"scaled": ["/n", "/n"], "op": "<"}, {"scaled": ["/n", "/n"], "op": "<", "value": 1},
                    {"scaled": ["/n", "/n"], "op": "<", "times": "2"},
                    {"scaled": ["/n", "/n"], "op": "<", "times": "unbounded"},
                    {"scaled": ["/n", "/n"], "op": "<", "times": True},
                    {"scaled": ["/n", "/n"], "op": "<", "times": None}, {"scaled": ["/n"], "op": "<", "times": 1},
                    {"scaled": ["/n", "/n", "/n"], "op": "<", "times": 1},
                    {"scaled": "/n", "op": "<", "times": 1}, {"scaled": ["/n", "n"], "op": "<", "times": 1},
                    {"scaled": ["/n", "/n"], "difference": ["/n", "/n"], "op": "<", "times": 1, "value": 1}]:
            self.assertRaises(cr.Fail, cr.test_pointers, bad)

    def test_all_any_not(self):
        yes, no = {"field": "/n", "op": "==", "value": 1}, {"field": "/n", "op": "==", "value": 2}
        gone = {"field": "/missing", "op": "!=", "value": 2}
        self.assertIs(self.check({"all": []}), True)
        self.assertIs(self.check({"any": []}), False)
        self.assertIs(self.check({"all": [yes, yes]}), True)
        self.assertIs(self.check({"all": [yes, no]}), False)
        self.assertIs(self.check({"any": [no, yes]}), True)
        self.assertIs(self.check({"any": [no, gone]}), False)
        self.assertIs(self.check({"not": yes}), False)
        self.assertIs(self.check({"not": no}), True)
        self.assertIs(self.check({"not": gone}), True)  # the inner test is false
        self.assertIs(self.check({"not": {"all": [yes, {"any": [no, {"not": no}]}]}}), False)

    def test_pointers(self):
        test = {"all": [{"field": "/a", "op": "==", "value": 1},
                        {"not": {"difference": ["/b/0", "/c"], "op": "<", "value": 1}},
                        {"any": [{"field": "", "op": "!=", "value": 1},
                                 {"not": {"scaled": ["/d", "/a"], "op": ">=", "times": 3}}]}]}
        self.assertEqual(cr.test_pointers(test), ["/a", "/b/0", "/c", "", "/d", "/a"])
        for bad in [[], {"all": [1]}, {"not": {}}, {"field": "/a", "op": "<"}, {"field": 3, "op": "<", "value": 1},
                    {"field": "/a~2", "op": "<", "value": 1}, {"all": [], "any": []}]:
            self.assertRaises(cr.Fail, cr.test_pointers, bad)


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

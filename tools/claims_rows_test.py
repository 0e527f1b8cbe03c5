"""Tests of tools/claims_rows.py: python3 tools/claims_rows_test.py

The row-test language of `membership` on one row: each form (field, difference, scaled, all, any,
not), what a pointer that finds nothing does, and the forms test_pointers refuses; and
check_membership's optional `and` (an intersection of selections over two made-up files held in
memory).  Membership claims over a made-up report folder: tools/verify_claims_test.py.
tools/claims_rules_test.py runs these tests too.
"""
import copy
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
if HERE not in sys.path:
    sys.path.insert(0, HERE)
import claims_rows as cr  # the row tests, pure functions over values


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


# Two made-up files: a sweep at two dt (key "method") and an energy table (key "name")
METHODS = [{"name": n, "exact_flow": n == "exact"} for n in ("forward_euler", "backward_euler", "trapezoid", "rk4", "exact")]
FILES = {
    "a.json": {"sweep": [  # at dt 0.5, numerical: stable forward_euler, backward_euler, trapezoid
        {"method": "forward_euler", "dt": 0.5, "stable": True}, {"method": "backward_euler", "dt": 0.5, "stable": True},
        {"method": "trapezoid", "dt": 0.5, "stable": True}, {"method": "rk4", "dt": 0.5, "stable": False},
        {"method": "exact", "dt": 0.5, "stable": True}, {"method": "rk4", "dt": 0.1, "stable": True}]},
    "b/b.json": {"energy": [  # numerical, drift < 0.1: backward_euler, trapezoid, rk4
        {"name": "forward_euler", "drift": 0.3}, {"name": "backward_euler", "drift": 0.01},
        {"name": "trapezoid", "drift": 0.001}, {"name": "rk4", "drift": 0.002}, {"name": "exact", "drift": 0}]}}
STABLE_AT = {"file": "a.json", "rows": "/sweep", "where": {"dt": 0.5}, "key": "method", "over": "numerical",
             "test": {"field": "/stable", "op": "==", "value": True}}
LOW_DRIFT = {"file": "b/b.json", "rows": "/energy", "where": {}, "key": "name", "over": "numerical",
             "test": {"field": "/drift", "op": "<", "value": 0.1}}
ITEMS_A = [("a.json", "/sweep/%d/stable" % i) for i in range(4)]  # the exact flow's row 4 is not numerical
ITEMS_B = [("b/b.json", "/energy/%d/drift" % i) for i in range(4)]


def rows_at(name, pointer):  # as verify_claims.py reads a file's rows: Fail where nothing is found
    ok, found = cr.find(FILES[name], pointer) if name in FILES else (False, "no file %s" % name)
    if not ok:
        raise cr.Fail("%s %s: %s" % (name, pointer, found))
    return found


ABSENT = object()


def claim(names, more=ABSENT, items=ITEMS_A + ITEMS_B):
    """The rule STABLE_AT with `and` = more (absent where ABSENT), its set `names`; and the
    evidence for `items`."""
    rule = dict(STABLE_AT, set=list(names), **({} if more is ABSENT else {"and": more}))
    return rule, [{"file": f, "pointer": p, "value": rows_at(f, p)} for f, p in items]


def check(names, more=ABSENT, items=ITEMS_A + ITEMS_B):
    return cr.check_membership(rows_at, METHODS, *claim(names, more, items))


class And(unittest.TestCase):
    """check_membership's optional `and`: the intersection of selections, each in its own file."""
    def test_intersection_over_two_files_holds(self):
        self.assertEqual(check(["trapezoid", "backward_euler"], [LOW_DRIFT]), [])
        self.assertEqual(check(["backward_euler", "trapezoid"], [LOW_DRIFT], ITEMS_B[::-1] + ITEMS_A), [])  # any order
        # a further selection in the first file: rk4 at dt 0.1 (stable) is in none of the others
        at_01 = dict(STABLE_AT, where={"dt": 0.1})
        self.assertEqual(check([], [LOW_DRIFT, at_01], ITEMS_A + ITEMS_B + [("a.json", "/sweep/5/stable")]), [])

    def test_absent_or_empty_and_is_the_rule_alone(self):
        three = ["forward_euler", "backward_euler", "trapezoid"]
        self.assertEqual(check(three, ABSENT, ITEMS_A), [])
        self.assertEqual(check(three, [], ITEMS_A), [])
        p = check(["backward_euler", "trapezoid"], ABSENT, ITEMS_A)
        self.assertEqual(p, ['set is ["backward_euler", "trapezoid"], the rows give '
                             '["backward_euler", "forward_euler", "trapezoid"]'])

    def test_a_method_only_one_selection_selects(self):
        for names in (["backward_euler", "trapezoid", "rk4"],  # rk4: the and only (unstable at dt 0.5)
                      ["forward_euler", "backward_euler", "trapezoid"],  # forward_euler: the rule only
                      ["backward_euler"]):
            p = check(names, [LOW_DRIFT])
            self.assertEqual(len(p), 1, (names, p))
            self.assertIn('the rows give ["backward_euler", "trapezoid"] (the rule\'s ["backward_euler", '
                          '"forward_euler", "trapezoid"], and[0]\'s ["backward_euler", "rk4", "trapezoid"])', p[0])

    def test_evidence_of_every_selection_in_its_own_file(self):
        both = ["backward_euler", "trapezoid"]
        p = check(both, [LOW_DRIFT], ITEMS_A + ITEMS_B[1:])  # one of the and's items missing
        self.assertEqual(p, ['evidence should be one item per row: 8 expected, 7 given, missing '
                             '["b/b.json#/energy/0/drift"], extra []'])
        self.assertTrue(check(both, [LOW_DRIFT], ITEMS_A))  # the and's items all missing
        self.assertTrue(check(both, [LOW_DRIFT], ITEMS_A[1:] + ITEMS_B))  # one of the rule's missing
        self.assertTrue(check(both, [LOW_DRIFT], ITEMS_A + ITEMS_B + ITEMS_B[:1]))  # one twice
        # the right pointer into the wrong file: a.json has no /energy, so the value is made up
        rule, evidence = claim(both, [LOW_DRIFT])
        evidence[4]["file"] = "a.json"
        p = cr.check_membership(rows_at, METHODS, rule, evidence)
        self.assertEqual(p, ['evidence should be one item per row: 8 expected, 8 given, missing '
                             '["b/b.json#/energy/0/drift"], extra ["a.json#/energy/0/drift"]'])
        # an item two selections share (the same file and pointer) is given once
        self.assertEqual(check(["forward_euler", "backward_euler", "trapezoid"], [STABLE_AT], ITEMS_A), [])
        self.assertTrue(check(["forward_euler", "backward_euler", "trapezoid"], [STABLE_AT], ITEMS_A + ITEMS_A))

    def test_malformed_and(self):
        names = ["backward_euler", "trapezoid"]
        lacking = {f: {k: v for k, v in LOW_DRIFT.items() if k != f} for f in LOW_DRIFT}
        for more, why in [(LOW_DRIFT, "not a list"), (None, "not a list"), ("b/b.json", "not a list"),
                          ([LOW_DRIFT, 42], "and[1]: 42 is not an object"), ([[LOW_DRIFT]], "and[0]: [")] + [
                ([lacking[f]], "is not an object with file, rows, where, key, over, test") for f in LOW_DRIFT] + [
                ([dict(LOW_DRIFT, over="some")], 'and[0]: over is "some"'),
                ([dict(LOW_DRIFT, over=None)], "and[0]: over is null"),
                ([dict(LOW_DRIFT, test={"field": "/drift", "op": "=~", "value": 1})], "and[0]: test "),
                ([dict(LOW_DRIFT, file="c.json")], "and[0]: c.json /energy: no file c.json"),
                ([dict(LOW_DRIFT, file=None)], "and[0]: file or rows is not a string"),
                ([dict(LOW_DRIFT, rows="/sweep")], "and[0]: b/b.json /sweep: no member"),
                ([dict(LOW_DRIFT, rows="/energy/0")], "and[0]: rows is not an array"),
                ([dict(LOW_DRIFT, where=[])], "and[0]: rows is not an array, where not an object"),
                ([dict(LOW_DRIFT, key="method")], 'and[0]: row 0 has no string "method"')]:
            with self.assertRaises(cr.Fail, msg=more) as raised:
                check(names, copy.deepcopy(more))
            self.assertIn(why, str(raised.exception), more)


if __name__ == "__main__":
    unittest.main()

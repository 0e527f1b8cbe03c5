"""The row-test language of a report's `membership` claims (docs/json.md, "A report's claims":
a *test* is a condition on one row) and the `membership` rule check, as pure functions over
values.  test_pointers checks a test's form and lists its pointers, holds evaluates it on a row,
check_membership the claim's rule on the rows its file holds (and on those of each selection of
its optional `and`, in their own files).  Values, pointers, Fail and the other kinds:
tools/claims_rules.py; reading the files and the claim loop: tools/verify_claims.py.  Standard
library only.
"""
import json
import math

from claims_rules import INFINITY_WORDS, THRESHOLD_OPS, Fail, find, is_number, same_json, show, \
    tokens

TEST_FORMS = ("field", "difference", "scaled", "all", "any", "not")

# --- tests, conditions on one row (membership) --------------------------------------------
def test_pointers(test):
    """Check a test's form (Fail where it has none) and list its pointers, nested ones too: a
    field's P, a difference's or a scaled's P1 and P2, those of the tests in all, any and not."""
    forms = [f for f in TEST_FORMS if f in test] if isinstance(test, dict) else []
    if len(forms) != 1:
        raise Fail("test %s is not an object with one of %s" % (show(test), ", ".join(TEST_FORMS)))
    form, op = forms[0], test.get("op")
    if form in ("all", "any", "not"):
        subs = [test["not"]] if form == "not" else test[form]
        if not isinstance(subs, list):
            raise Fail("test %s: %s is not a list of tests" % (show(test), form))
        return [p for sub in subs for p in test_pointers(sub)]
    ops = ("==", "!=", *THRESHOLD_OPS) if form == "field" else tuple(THRESHOLD_OPS)
    operand = "times" if form == "scaled" else "value"
    if not isinstance(op, str) or op not in ops or operand not in test:
        raise Fail("test %s: op not one of %s, or no %s"
                   % (show(test), ", ".join(map(json.dumps, ops)), operand))
    if form == "scaled" and not is_number(test["times"]):
        raise Fail("test %s: times is not a number" % show(test))
    pointers = [test["field"]] if form == "field" else test[form]
    if not isinstance(pointers, list) or len(pointers) != (1 if form == "field" else 2):
        raise Fail("test %s: %s is not two pointers" % (show(test), form))
    try:
        return [p for p in pointers if tokens(p) is not None]  # tokens: Fail if not one
    except Fail as why:
        raise Fail("test %s: %s" % (show(test), why))

def as_number(v):
    """A value in a test as a number: +infinity for the words, None for null or a non-number."""
    return float(v) if is_number(v) else math.inf if v in INFINITY_WORDS else None

def holds(test, row):
    """Whether a test (that test_pointers accepted) holds on the row.  {"field": P, "op", "value":
    V}: x what P finds in the row; "==", "!=": x (not) raw-JSON equal to V; "<", "<=", ">", ">=":
    x and V as numbers (the words +infinity), false where either is null or not a number.
    {"difference": [P1, P2], "op", "value": V}: |x1 - x2| op V, false where x1 or x2 is null, not
    a number or +infinity.  {"scaled": [P1, P2], "op", "times": c}: x1 op c x2, x1 and x2 as
    numbers (the words +infinity), false where either is null or not a number (c x2 in floating
    point: 0 x +infinity is no number, and no op holds on it).  {"all": [...]} (true for none),
    {"any": [...]} (false for none), {"not": test}.  A pointer that finds nothing in the row makes
    its test false ("!=" too)."""
    if "all" in test:
        return all(holds(t, row) for t in test["all"])
    if "any" in test:
        return any(holds(t, row) for t in test["any"])
    if "not" in test:
        return not holds(test["not"], row)
    form = next(f for f in ("field", "difference", "scaled") if f in test)
    found = [find(row, p) for p in ([test["field"]] if form == "field" else test[form])]
    if not all(ok for ok, _ in found):
        return False
    op, xs = test["op"], [as_number(x) for _, x in found]
    if op in ("==", "!="):  # "field" only
        return same_json(found[0][1], test["value"]) == (op == "==")
    if any(x is None for x in xs):
        return False
    if form == "scaled":
        return THRESHOLD_OPS[op](xs[0], test["times"] * xs[1])
    if form == "difference":
        if math.inf in xs:
            return False
        xs = [abs(xs[0] - xs[1])]
    limit = as_number(test["value"])
    return limit is not None and THRESHOLD_OPS[op](xs[0], limit)

# --- the membership kind ------------------------------------------------------------------
SELECTION_FIELDS = ("file", "rows", "where", "key", "over", "test")  # of the rule and of each `and`

def select(rows_at, methods, sel):
    """One selection ({"file", "rows", "where", "key", "over", "test"}: the rule itself or one of
    its `and`), `rows_at(file, pointer)` what the pointer finds in that file under data/ (Fail
    where nothing).  ({row[key] : row passes `where` and `over`, and `test` holds on it}, the
    evidence items it asks for: for each row passing `where` and `over`, (file, rows/i + P) for
    each pointer P of the test that finds a value in the row)."""
    if not isinstance(sel, dict) or any(f not in sel for f in SELECTION_FIELDS):
        raise Fail("%s is not an object with %s" % (show(sel), ", ".join(SELECTION_FIELDS)))
    key, test, where, over = sel["key"], sel["test"], sel["where"], sel["over"]
    if not isinstance(sel["file"], str) or not isinstance(sel["rows"], str):
        raise Fail("file or rows is not a string")
    rows = rows_at(sel["file"], sel["rows"])
    if not isinstance(rows, list) or not isinstance(where, dict) or not isinstance(key, str):
        raise Fail("rows is not an array, where not an object, or key not a string")
    pointers = list(dict.fromkeys(test_pointers(test)))  # each pointer once
    if over == "numerical":
        if not isinstance(methods, list) or not all(isinstance(m, dict) for m in methods):
            raise Fail("over is \"numerical\" but methods is not a list of objects")
        allowed = {m.get("name") for m in methods if m.get("exact_flow") is False}
    elif over != "all":
        raise Fail("over is %s, not \"numerical\" or \"all\"" % show(over))
    found, expected = set(), []
    for i, row in enumerate(rows):
        if not isinstance(row, dict):
            raise Fail("row %d of %s is not an object" % (i, sel["rows"]))
        if not all(f in row and same_json(row[f], v) for f, v in where.items()):
            continue
        if not isinstance(row.get(key), str):
            raise Fail("row %d has no string %s" % (i, show(key)))
        if over == "numerical" and row[key] not in allowed:
            continue
        expected += [(sel["file"], "%s/%d%s" % (sel["rows"], i, p)) for p in pointers
                     if find(row, p)[0]]
        if holds(test, row):
            found.add(row[key])
    return found, expected

def check_membership(rows_at, methods, rule, evidence):
    """`rows_at(file, pointer)` what the pointer finds in a file under data/ (Fail where it finds
    nothing), `methods` the claims file's.  The rule selects a set and its items (select); so
    does each of its optional `and`, a list of {"file", "rows", "where", "key", "over", "test"}
    read as the rule's own.  set == the intersection of the sets; and the evidence is every
    selection's items, each (that selection's file, pointer) once, in any order, no more and no
    fewer.  Without `and`: set == the rule's, its items the evidence, as before."""
    want, more = rule["set"], rule.get("and", [])
    if not isinstance(want, list) or not all(isinstance(s, str) for s in want):
        raise Fail("set is not a list of strings")
    if not isinstance(more, list):
        raise Fail("and is %s, not a list of selections" % show(more))
    found, expected = select(rows_at, methods, rule)
    sets = [found]
    for k, sel in enumerate(more):
        try:
            got_set, items = select(rows_at, methods, sel)
        except Fail as why:
            raise Fail("and[%d]: %s" % (k, why))
        sets.append(got_set)
        found = found & got_set
        expected += items
    expected = list(dict.fromkeys(expected))  # an item two selections share: once
    problems = []
    if found != set(want):
        why = "set is %s, the rows give %s" % (show(sorted(set(want))), show(sorted(found)))
        if "and" in rule:
            why += " (%s)" % ", ".join(["the rule's %s" % show(sorted(sets[0]))] + [
                "and[%d]'s %s" % (k, show(sorted(s))) for k, s in enumerate(sets[1:])])
        problems.append(why)
    got = [(e.get("file"), e.get("pointer")) for e in evidence]
    if sorted(got, key=str) != sorted(expected, key=str):
        name = (lambda f, p: "%s#%s" % (f, p)) if "and" in rule else (lambda f, p: p)
        problems.append("evidence should be one item per row: %d expected, %d given, missing %s, "
                        "extra %s" % (len(expected), len(got),
                                      show([name(f, p) for f, p in expected if (f, p) not in got]),
                                      show([name(f, p) for f, p in got if (f, p) not in expected])))
    return problems

"""Two kinds of a report's claims (docs/json.md, "A report's claims") beside claims_rules.py's:
`extreme` (a value is the least or the greatest of a list, as printed: what a figure's caption
says of its curves) and `mismatch` (how many cells of two equally shaped arrays differ: the
stability map's measured verdicts against the step map's prediction).  Pure functions over the
evidence values; claims_rules.CHECKS holds them.  Standard library only.
"""
import math

from claims_rules import Fail, as_printed, checked_digits, is_index, printed_number, same_json, show, to_number
from fractions import Fraction

WHICH = {"least": lambda a, x: a <= x, "greatest": lambda a, x: a >= x}


def item_value(item, x):
    """An item of `a` or `others`: an index k (the value x[k]) or [i, j] (x[i] - x[j])."""
    if isinstance(item, list):
        a, b = x[item[0]], x[item[1]]
        return None if a is None or b is None else a - b
    return x[item]


def check_extreme(rule, values):
    """a is the least ("which": "least") or the greatest ("greatest") of itself and the items of
    `others` (a tie with another is allowed: a is one of the least), where an item is an evidence
    index k (its value) or a pair [i, j] (evidence i's value minus evidence j's); where `printed`
    is a string, a is `printed` to `digits` as a ratio is (|a - printed| <= half a unit of its
    last place + 10^-9 |a|).  "unbounded" and "never" are +infinity (never printed); a null value
    fails it."""
    i, others, which = rule["a"], rule["others"], rule["which"]
    items = [i] + others if isinstance(others, list) else None
    is_item = lambda k: is_index(k, values) or (isinstance(k, list) and len(k) == 2 and all(is_index(j, values) for j in k))
    if items is None or not all(is_item(k) for k in items):
        raise Fail("a %s or others %s is not an evidence index or a pair of them (of %d values)"
                   % (show(i), show(others), len(values)))
    if which not in WHICH:
        raise Fail("which is %s, not \"least\" or \"greatest\"" % show(which))
    read = sorted({j for k in items for j in (k if isinstance(k, list) else [k])})
    x = {k: to_number(values[k], "evidence %d" % k) for k in read}
    nulls = [k for k in read if x[k] is None]
    if nulls:
        return ["evidence %s null (not measured)" % ", ".join(map(str, nulls))]
    a = item_value(i, x)
    if isinstance(a, float) and math.isnan(a):
        return ["a %s is infinity minus infinity" % show(i)]
    problems = ["a %s is %s, not the %s: %s is %s" % (show(i), show(a), which, show(k), show(item_value(k, x)))
                for k in others if not WHICH[which](a, item_value(k, x))]
    if rule.get("printed") is not None:
        digits = rule.get("digits")
        how, n = checked_digits(digits)
        p = printed_number(rule["printed"], "printed")
        if not math.isfinite(a):
            problems.append("a %s is %s, not a finite number to print" % (show(i), show(a)))
        elif isinstance(i, list):
            raise Fail("a difference is not printed")
        elif not as_printed(Fraction(a), p, digits):
            problems.append("a %s %.12g is not %s to %d %s" % (
                show(i), a, show(rule["printed"]), n, "decimals" if how == "decimals" else "significant digits"))
    return problems


def leaves(x):
    """The scalars of a nested list, in order, and its shape (nested lengths)."""
    if not isinstance(x, list):
        return [x], None
    out, shapes = [], []
    for y in x:
        ys, s = leaves(y)
        out += ys
        shapes.append(s)
    return out, (len(x), shapes)


def check_mismatch(rule, values):
    """For each pair [i, j], evidence i and j are arrays of the same nested shape; the number of
    positions where their scalars differ (as raw JSON: true is not 1), summed over the pairs, is
    `count`."""
    pairs, n = rule["pairs"], rule["count"]
    if not isinstance(pairs, list) or not all(
            isinstance(p, list) and len(p) == 2 and all(is_index(k, values) for k in p) for p in pairs):
        raise Fail("pairs %s is not a list of [i, j] evidence indices" % show(pairs))
    if not isinstance(n, int) or isinstance(n, bool) or n < 0:
        raise Fail("count %s is not an integer >= 0" % show(n))
    if not pairs:
        return ["pairs is empty"]
    problems, differ = [], 0
    for i, j in pairs:
        (xs, sx), (ys, sy) = leaves(values[i]), leaves(values[j])
        if sx is None or sy is None or sx != sy:
            problems.append("pair [%d, %d]: not two arrays of the same shape" % (i, j))
        else:
            differ += sum(not same_json(a, b) for a, b in zip(xs, ys))
    if not problems and differ != n:
        problems.append("%d cells differ, the claim says %d" % (differ, n))
    return problems

"""The rules of a report's claims (docs/json.md, "A report's claims"), as pure functions over
values: RFC 6901 pointers into a value, and each kind's rule check but membership's (trend,
statistic, comparison, threshold, equality, ratio, count; extreme and mismatch in
claims_extremes.py).  A check returns the list of reasons
its claim does not hold ([] where it holds) and raises Fail where the rule cannot be evaluated
(which does not hold either).  The row-test language and the membership check:
tools/claims_rows.py; reading the files and the claim loop: tools/verify_claims.py.  Standard
library only.
"""
import json
import math
import re
from fractions import Fraction

INFINITY_WORDS = ("unbounded", "never")  # both stand for +infinity where a number is needed
RULE_FIELDS = {
    "membership": ("file", "rows", "where", "key", "over", "test", "set"),
    "trend": ("along", "relative", "trend"),
    "statistic": ("statistic", "x", "y", "value", "decimals", "words"),
    "comparison": ("a", "others", "relation", "margin", "noise"),
    "threshold": ("op", "limit"),  # and optionally "items"
    "equality": ("pairs", "relative", "absolute"),
    "ratio": ("ratios", "least", "greatest", "digits"),
    "count": ("groups", "count"),
    "extreme": ("a", "others", "which"),  # and optionally "printed", "digits"
    "mismatch": ("pairs", "count"),
}
GROUP_KINDS = ("equality", "comparison", "threshold")  # the kinds a `count` group may have
THRESHOLD_OPS = {"<": lambda v, l: v < l, "<=": lambda v, l: v <= l,
                 ">": lambda v, l: v > l, ">=": lambda v, l: v >= l}

class Fail(Exception): pass  # a reason a claim does not hold

# --- values and RFC 6901 pointers -------------------------------------------------------
def show(v):
    return "inf" if v == math.inf else json.dumps(v)

def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)

def is_index(k, values):
    return isinstance(k, int) and not isinstance(k, bool) and 0 <= k < len(values)

def same_json(a, b):
    """Raw JSON equality: numbers by value (1 == 1.0, exactly), true is not 1, and so on."""
    if is_number(a) and is_number(b):
        return a == b
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same_json(x, y) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same_json(a[k], b[k]) for k in a)
    return type(a) is type(b) and a == b

def unescape(token):
    """RFC 6901 reference token: ~1 is '/', ~0 is '~'; any other '~' is an error."""
    head, *rest = token.split("~")
    if any(part[:1] not in ("0", "1") for part in rest):
        raise Fail("bad escape in pointer token %s" % json.dumps(token))
    return head + "".join(("~" if part[0] == "0" else "/") + part[1:] for part in rest)

def tokens(pointer):
    """RFC 6901: "" is the whole document, else "/t1/t2..."; Fail if `pointer` is not one."""
    if not isinstance(pointer, str) or (pointer and not pointer.startswith("/")):
        raise Fail("pointer %s is not an RFC 6901 pointer" % show(pointer))
    return [unescape(raw) for raw in pointer.split("/")[1:]] if pointer else []

def find(node, pointer):
    """(True, what `pointer` finds in node) or (False, why it finds nothing); array tokens are
    0 or [1-9][0-9]*.  Fail only for a pointer that is not one."""
    for token in tokens(pointer):
        if isinstance(node, dict):
            if token not in node:
                return False, "no member %s" % json.dumps(token)
            node = node[token]
        elif isinstance(node, list):
            if not (token.isascii() and token.isdigit()) or token != str(int(token)) \
                    or int(token) >= len(node):
                return False, "no element %s in an array of %d" % (token, len(node))
            node = node[int(token)]
        else:
            return False, "%s is not an object or array" % json.dumps(token)
    return True, node

def to_number(v, what):
    """A value where a number is needed: "unbounded" and "never" are +infinity, null is None."""
    if is_number(v) or v is None:
        return v if v is None else float(v)
    if v in INFINITY_WORDS:
        return math.inf
    raise Fail("%s is %s, not a number, \"unbounded\", \"never\" or null" % (what, show(v)))

# --- trend --------------------------------------------------------------------------------
# Values x_0 .. x_n (+infinity for "unbounded"/"never", None for null):
#   "not measured"    if any x_i is null;
#   "stays unbounded" if every x_i is +infinity;
#   else each consecutive pair (a, b) is the same if a == b (+infinity equals +infinity only)
#   or both are finite with |a - b| <= r max(|a|, |b|); a pair not the same goes up if b > a
#   (+infinity is above every number), down otherwise.  Then "rises" (some up, none down),
#   "falls" (some down, none up), "stays the same" (neither), "does not move one way" (both).
def trend_of(values, relative):
    if any(v is None for v in values):
        return "not measured"
    if all(v == math.inf for v in values):
        return "stays unbounded"
    up = down = False
    for a, b in zip(values, values[1:]):
        finite = a != math.inf and b != math.inf
        if a == b or (finite and abs(a - b) <= relative * max(abs(a), abs(b))):
            continue
        up, down = up or b > a, down or b < a
    return {(True, False): "rises", (False, True): "falls",
            (False, False): "stays the same", (True, True): "does not move one way"}[(up, down)]

# --- Spearman -----------------------------------------------------------------------------
# Each list is ranked 1..n among itself (+infinity above every number); tied values share the
# average of the ranks they span.  We keep twice the rank, an integer (Pearson's r does not
# change under scaling).  With S_x = sum x, S_xx = sum x^2, S_xy = sum x y over the n points:
#   cov = n S_xy - S_x S_y,  var_x = n S_xx - S_x^2,  rho = cov / sqrt(var_x var_y)
# (the Pearson correlation of the ranks), and rho = 0 where either ranking is constant
# (var = 0).  Words, decided in integers so that no rounding moves a threshold:
#   |rho| < 0.3  <=>  100 cov^2 <  9 var_x var_y   -> "weak"
#   |rho| < 0.7  <=>  100 cov^2 < 49 var_x var_y   -> "moderate", else "strong";
#   then " positive" if rho >= 0 (cov >= 0), else " negative".
def doubled_ranks(values):
    # twice the average rank of v: 2 #{u < v} + #{u == v} + 1 (ranks #{u < v} + 1 .. #{u <= v})
    return [2 * sum(u < v for u in values) + sum(u == v for u in values) + 1 for v in values]

def spearman(xs, ys):
    """Return (rho, words) for two equal-length lists of floats (math.inf allowed)."""
    rx, ry, n = doubled_ranks(xs), doubled_ranks(ys), len(xs)
    cov = n * sum(a * b for a, b in zip(rx, ry)) - sum(rx) * sum(ry)
    var_x = n * sum(a * a for a in rx) - sum(rx) ** 2
    var_y = n * sum(b * b for b in ry) - sum(ry) ** 2
    if var_x == 0 or var_y == 0:
        return 0.0, "weak positive"
    rho = cov / (math.sqrt(var_x) * math.sqrt(var_y))
    c2, v2 = 100 * cov * cov, var_x * var_y
    strength = "weak" if c2 < 9 * v2 else "moderate" if c2 < 49 * v2 else "strong"
    return rho, strength + (" positive" if cov >= 0 else " negative")

# --- ratio --------------------------------------------------------------------------------
# A ratio is prod(over) / prod(under) (an empty product is 1), computed exactly in fractions of
# the values (each JSON number is exactly a binary fraction).  A printed L is taken exactly
# too; it is "r as printed" when |r - L| <= half a unit of L's last printed place,
#   {"decimals": d}:    0.5 10^-d
#   {"significant": s}: 0.5 10^(e - s + 1), e = floor(log10 |L|) (L = 0: r must be 0),
# plus a slack of 10^-9 |r| for the writer's floating-point arithmetic.
PRINTED = re.compile(r"-?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")  # "1.23e+03", "180"
SLACK = Fraction(1, 10 ** 9)

def printed_number(text, what):
    """The exact value of a printed decimal number; Fail where `text` is not one (float()
    would also take "nan", "inf", " 1" and "1_0")."""
    if not isinstance(text, str) or not PRINTED.fullmatch(text):
        raise Fail("%s is %s, not a number as printed" % (what, show(text)))
    return Fraction(text)

def decade(x):
    """floor(log10 x) for a Fraction x > 0, exactly."""
    e = len(str(x.numerator)) - len(str(x.denominator))  # within one of the answer
    while Fraction(10) ** e > x:
        e -= 1
    while Fraction(10) ** (e + 1) <= x:
        e += 1
    return e

def half_unit(printed, digits):
    """Half a unit of the last place of `printed` (a Fraction) rounded as `digits` says; None
    where r must equal it exactly (0 to significant digits)."""
    (how, n), = digits.items()  # one, as check_ratio made sure
    if how == "decimals":
        return Fraction(1, 2) / Fraction(10) ** n
    return None if printed == 0 else Fraction(1, 2) * Fraction(10) ** (decade(abs(printed)) - n + 1)

def checked_digits(digits):
    """(how, n) of a rule's `digits`: {"decimals": d >= 0} or {"significant": s >= 1}."""
    how, n = next(iter(digits.items())) if isinstance(digits, dict) and len(digits) == 1 \
        else (None, None)
    if how not in ("decimals", "significant") or not isinstance(n, int) or isinstance(n, bool) \
            or n < (0 if how == "decimals" else 1):
        raise Fail("digits is %s, not {\"decimals\": d >= 0} or {\"significant\": s >= 1}"
                   % show(digits))
    return how, n

def as_printed(r, x, digits):
    """Whether the exact value r is x (the exact value of a printed number) to `digits`."""
    half = half_unit(x, digits)
    return r == x if half is None else abs(r - x) <= half + SLACK * abs(r)

def check_ratio(rule, values):
    """Each ratio prod(over) / prod(under) of evidence values (an empty product is 1); the least
    ratio as printed to `digits` is `least`, the greatest `greatest`.  Holds when `ratios` is not
    empty, every value read is a finite number (null, "unbounded" and "never" are not), every
    under product is above 0, and |r - L| <= half a unit of L's last place + 10^-9 |r| for the
    least (L `least`) and the greatest (L `greatest`)."""
    ratios, digits = rule["ratios"], rule["digits"]
    if not isinstance(ratios, list) or not all(
            isinstance(q, dict) and all(isinstance(q.get(f), list) and all(
                is_index(k, values) for k in q[f]) for f in ("over", "under")) for q in ratios):
        raise Fail("ratios %s is not a list of {\"over\", \"under\"} lists of indices into the %d "
                   "evidence values" % (show(ratios), len(values)))
    how, n = checked_digits(digits)
    printed = {w: printed_number(rule[w], w) for w in ("least", "greatest")}
    if not ratios:
        return ["ratios is empty"]
    read = sorted({k for q in ratios for k in q["over"] + q["under"]})
    problems = ["evidence %d is %s, not a finite number" % (k, "null (not measured)"
                if values[k] is None else show(values[k]))
                for k in read if not is_number(values[k]) or values[k] in (math.inf, -math.inf)]
    if problems:
        return problems
    exact = lambda ks: math.prod((Fraction(values[k]) for k in ks), start=Fraction(1))
    under = [exact(q["under"]) for q in ratios]
    problems = ["ratio %d: the under product %s is not above 0" % (i, show(float(u)))
                for i, u in enumerate(under) if not u > 0]
    if problems:
        return problems
    rs = [exact(q["over"]) / u for q, u in zip(ratios, under)]
    for word, r in (("least", min(rs)), ("greatest", max(rs))):
        x, half = printed[word], half_unit(printed[word], digits)
        if not as_printed(r, x, digits):
            problems.append("the %s ratio %.12g (ratio %d) is not %s to %d %s: %s" % (
                word, r, rs.index(r), show(rule[word]), n,
                "decimals" if how == "decimals" else "significant digits",
                "it is not 0" if half is None else "off by %.3g, above %.3g + %.3g"
                % (abs(r - x), half, SLACK * abs(r))))
    return problems

# --- the other kinds ----------------------------------------------------------------------
def check_trend(rule, values):
    """One value per name of `along`; their trend (trend_of, relative r) is the rule's word."""
    along, r = rule["along"], rule["relative"]
    if not isinstance(along, list) or not along or len(values) != len(along):
        raise Fail("along %s does not name one value per evidence item (%d)"
                   % (show(along), len(values)))
    if not is_number(r) or r < 0:
        raise Fail("relative is %s, not a number >= 0" % show(r))
    xs = [to_number(v, "the value for %s" % show(n)) for v, n in zip(values, along)]
    word = trend_of(xs, r)
    if word == rule["trend"]:
        return []
    return ["trend of [%s] (relative %s) is %s, the claim says %s"
            % (", ".join(map(show, xs)), show(r), show(word), show(rule["trend"]))]

def check_statistic(rule, values):
    """Spearman's rho of the points (evidence[x[k]], evidence[y[k]]) is `value` to `decimals`
    (|rho - value| <= 0.5 10^-decimals) and `words` are rho's; a null value fails."""
    if rule["statistic"] != "spearman":
        raise Fail("unknown statistic %s" % show(rule["statistic"]))
    x, y, d = rule["x"], rule["y"], rule["decimals"]
    if not isinstance(x, list) or not isinstance(y, list) or not x or len(x) != len(y) \
            or not all(is_index(i, values) for i in x + y):
        raise Fail("x %s and y %s are not equal-length lists of evidence indices"
                   % (show(x), show(y)))
    if not isinstance(d, int) or isinstance(d, bool) or d < 0 or not is_number(rule["value"]):
        raise Fail("value %s or decimals %s is not a number" % (show(rule["value"]), show(d)))
    pts = [(to_number(values[i], "evidence %d" % i), to_number(values[j], "evidence %d" % j))
           for i, j in zip(x, y)]
    if any(a is None or b is None for a, b in pts):
        raise Fail("a point has a null value: %s" % show([[show(a), show(b)] for a, b in pts]))
    rho, words = spearman([a for a, _ in pts], [b for _, b in pts])
    # |rho - value| <= 0.5 10^-decimals; the factor 1 + 1e-9 only absorbs the binary
    # representation of the decimal `value` (a rounding exactly at the half-way point).
    problems = []
    if not abs(rho - rule["value"]) <= 0.5 * 10.0 ** -d * (1 + 1e-9):
        problems.append("rho is %.*f, the claim says %s to %d decimals"
                        % (d + 2, rho, show(rule["value"]), d))
    if words != rule["words"]:
        problems.append("rho %.4f is %s, the claim says %s"
                        % (rho, show(words), show(rule["words"])))
    return problems

def check_comparison(rule, values):
    """a = evidence[i], B the least of `others` (+infinity where empty), M = max(margin, product
    of the `noise` values) (the margin where `noise` is empty).  Holds when no value is null,
    a <= every other, and "less": B >= M a and B > a; "tie": B < M a or B == a, and
    evidence[others[0]] == B."""
    i, others, noise, m = rule["a"], rule["others"], rule["noise"], rule["margin"]
    if not isinstance(others, list) or not isinstance(noise, list) \
            or not all(is_index(k, values) for k in [i] + others + noise):
        raise Fail("a %s, others %s or noise %s is not an index into the %d evidence values"
                   % (show(i), show(others), show(noise), len(values)))
    if rule["relation"] not in ("less", "tie"):
        raise Fail("relation is %s, not \"less\" or \"tie\"" % show(rule["relation"]))
    if not is_number(m):
        raise Fail("margin is %s, not a number" % show(m))
    x = {k: to_number(values[k], "evidence %d" % k) for k in [i] + others + noise}
    nulls = sorted(k for k, v in x.items() if v is None)
    if nulls:  # does not hold (a count's group too), unlike a rule that cannot be evaluated
        return ["evidence %s null (not measured)" % ", ".join(map(str, nulls))]
    a, big_m = x[i], max(m, math.prod(x[k] for k in noise)) if noise else m
    b, ma = min((x[k] for k in others), default=math.inf), big_m * a
    problems = ["a (evidence %d) is %s, above evidence %d (%s)" % (i, show(a), k, show(x[k]))
                for k in others if not a <= x[k]]
    if rule["relation"] == "less" and not (b >= ma and b > a):
        problems.append("less: the least other %s is not >= M a = %s x %s = %s and > a"
                        % (show(b), show(big_m), show(a), show(ma)))
    if rule["relation"] == "tie":
        if not (b < ma or b == a):
            problems.append("tie: the least other %s is neither < M a = %s x %s = %s nor == a"
                            % (show(b), show(big_m), show(a), show(ma)))
        if not others:
            problems.append("tie: others is empty, nothing to tie with")
        elif x[others[0]] != b:
            problems.append("tie: the first of others (evidence %d) is %s, not the least, %s"
                            % (others[0], show(x[others[0]]), show(b)))
    return problems

def check_threshold(rule, values):
    """The items (evidence indices `items`, all of the evidence where absent) are not empty and
    every item's value v (+infinity for "unbounded"/"never") has v op limit; a null value fails."""
    op, limit = rule["op"], rule["limit"]
    items = rule.get("items", list(range(len(values))))
    if not isinstance(items, list) or not all(is_index(k, values) for k in items):
        raise Fail("items %s is not a list of indices into the %d evidence values"
                   % (show(items), len(values)))
    if not isinstance(op, str) or op not in THRESHOLD_OPS:
        raise Fail("op is %s, not one of %s"
                   % (show(op), ", ".join(map(json.dumps, THRESHOLD_OPS))))
    if not is_number(limit):
        raise Fail("limit is %s, not a number" % show(limit))
    if not items:
        return ["the items are empty" if "items" in rule else "the evidence is empty"]
    problems = []
    for k in items:
        x = to_number(values[k], "evidence %d" % k)
        if x is None:
            problems.append("evidence %d is null (not measured), not %s %s" % (k, op, show(limit)))
        elif not THRESHOLD_OPS[op](x, limit):
            problems.append("evidence %d is %s, not %s %s" % (k, show(x), op, show(limit)))
    return problems

def check_equality(rule, values):
    """`pairs` not empty, and for each pair [i, j] the values x, y (+infinity for the words) are
    equal: x == y (+infinity equals +infinity only) or both finite with |x - y| <= max(a, r
    max(|x|, |y|)), r `relative`, a `absolute`; a null value fails."""
    pairs, r, a = rule["pairs"], rule["relative"], rule["absolute"]
    if not isinstance(pairs, list) or not all(isinstance(p, list) and len(p) == 2 and all(
            is_index(k, values) for k in p) for p in pairs):
        raise Fail("pairs %s is not a list of [i, j] indices into the %d evidence values"
                   % (show(pairs), len(values)))
    if not all(is_number(t) and t >= 0 for t in (r, a)):
        raise Fail("relative %s or absolute %s is not a number >= 0" % (show(r), show(a)))
    if not pairs:
        return ["pairs is empty"]
    problems = []
    for i, j in pairs:
        x, y = to_number(values[i], "evidence %d" % i), to_number(values[j], "evidence %d" % j)
        if x is None or y is None:
            problems.append("pair [%d, %d]: a null value (not measured)" % (i, j))
        elif x != y and math.inf in (x, y):
            problems.append("pair [%d, %d]: %s and %s, +infinity equals no number"
                            % (i, j, show(x), show(y)))
        elif x != y and abs(x - y) > max(a, r * max(abs(x), abs(y))):
            problems.append("pair [%d, %d]: %s and %s differ by %.6g, above max(%s, %s x %s)" % (
                i, j, show(x), show(y), abs(x - y), show(a), show(r), show(max(abs(x), abs(y)))))
    return problems

def check_count(rule, values):
    """Exactly `count` of `groups` hold, each group {"kind", "rule"} of kind equality, comparison
    or threshold over this claim's evidence (a null value: the group does not hold); a group
    whose kind or rule cannot be evaluated makes the claim fail."""
    groups, n = rule["groups"], rule["count"]
    if not isinstance(groups, list) or not isinstance(n, int) or isinstance(n, bool) or n < 0:
        raise Fail("groups %s is not a list or count %s not an integer >= 0"
                   % (show(groups), show(n)))
    held = []
    for g, group in enumerate(groups):
        try:
            if not isinstance(group, dict) or group.get("kind") not in GROUP_KINDS:
                raise Fail("not an object of kind %s" % ", ".join(map(json.dumps, GROUP_KINDS)))
            if not CHECKS[group["kind"]](checked_rule(group["kind"], group.get("rule")), values):
                held.append(g)
        except Fail as why:
            raise Fail("group %d: %s" % (g, why))
    if len(held) == n:
        return []
    return ["%d of the %d groups hold (%s), the claim says %d"
            % (len(held), len(groups), show(held), n)]

CHECKS = {"trend": check_trend, "statistic": check_statistic, "comparison": check_comparison,
          "threshold": check_threshold, "equality": check_equality, "ratio": check_ratio,
          "count": check_count}

def checked_rule(kind, rule):
    if not isinstance(rule, dict) or any(f not in rule for f in RULE_FIELDS[kind]):
        raise Fail("rule lacks one of %s" % ", ".join(RULE_FIELDS[kind]))
    return rule

# extreme and mismatch (a caption's least or greatest, the map's cells): claims_extremes.py,
# imported last since it reads this module's helpers
from claims_extremes import check_extreme, check_mismatch  # noqa: E402
CHECKS.update(extreme=check_extreme, mismatch=check_mismatch)

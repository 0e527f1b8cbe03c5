#!/usr/bin/env python3
"""Re-evaluate a report's claims: python3 tools/verify_claims.py REPORT_DIR

Reads REPORT_DIR/data/claims.json (schema "steplab.claims/1", docs/json.md, "A report's claims")
and the data files its evidence names, and re-evaluates every claim with code of its own.
Prints `<id>: <why>` for each claim that does not hold, then `claims: N, hold: H, do not hold: F`.
Exit 0: every claim holds; 1: some claim does not; 2: claims.json missing, not JSON or not
steplab.claims/1.  Standard library only.
"""
import json
import math
import os
import sys

SCHEMA = "steplab.claims/1"
INFINITY_WORDS = ("unbounded", "never")  # both stand for +infinity where a number is needed
CLAIM_FIELDS = ("id", "section", "sentence", "kind", "rule", "evidence")
RULE_FIELDS = {
    "membership": ("file", "rows", "where", "key", "over", "field", "equals", "set"),
    "trend": ("along", "relative", "trend"),
    "statistic": ("statistic", "x", "y", "value", "decimals", "words"),
    "comparison": ("a", "others", "relation", "margin", "noise"),
    "threshold": ("op", "limit"),
}
THRESHOLD_OPS = {"<": lambda v, l: v < l, "<=": lambda v, l: v <= l,
                 ">": lambda v, l: v > l, ">=": lambda v, l: v >= l}

class Fail(Exception): pass  # a reason a claim does not hold
class BadClaimsFile(Exception): pass  # claims.json itself is unusable: exit status 2

def show(v):
    return "inf" if v == math.inf else json.dumps(v)

def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)

def load_json(path):
    def reject(name):  # Python would otherwise accept NaN and Infinity
        raise ValueError("%s is not JSON" % name)
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_constant=reject)

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

def resolve(doc, pointer):
    """RFC 6901: "" is the whole document; else "/t1/t2...", array tokens 0 or [1-9][0-9]*."""
    if not isinstance(pointer, str) or (pointer and not pointer.startswith("/")):
        raise Fail("pointer %s is not an RFC 6901 pointer" % show(pointer))
    node = doc
    for raw in pointer.split("/")[1:] if pointer else []:
        token = unescape(raw)
        if isinstance(node, dict):
            if token not in node:
                raise Fail("pointer %s: no member %s" % (pointer, json.dumps(token)))
            node = node[token]
        elif isinstance(node, list):
            if not (token.isascii() and token.isdigit()) or token != str(int(token)) \
                    or int(token) >= len(node):
                raise Fail("pointer %s: no element %s in an array of %d"
                           % (pointer, token, len(node)))
            node = node[int(token)]
        else:
            raise Fail("pointer %s: %s is not an object or array" % (pointer, json.dumps(token)))
    return node

class Report:
    """A report folder; data files are read once, relative to REPORT_DIR/data/."""
    def __init__(self, report_dir):
        self.data, self.cache = os.path.join(report_dir, "data"), {}

    def file(self, name):
        if not isinstance(name, str) or not name or os.path.isabs(name) \
                or ".." in name.replace("\\", "/").split("/"):
            raise Fail("file %s is not a path under data/" % show(name))
        if name not in self.cache:
            try:
                self.cache[name] = load_json(os.path.join(self.data, name))
            except FileNotFoundError:
                raise Fail("file %s is missing" % name)
            except (OSError, ValueError) as e:
                raise Fail("file %s is not readable JSON (%s)" % (name, e))
        return self.cache[name]

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

# --- the kinds ----------------------------------------------------------------------------
def check_membership(report, doc, rule, evidence):
    """set == {row[key] : row passes `where` and `over`, row[field] == equals}; and one
    evidence item (rule file, rows/i/field) for each row passing `where` and `over`."""
    rows = resolve(report.file(rule["file"]), rule["rows"])
    key, field, want = rule["key"], rule["field"], rule["set"]
    strings = want + [key, field] if isinstance(want, list) else [None]
    if not isinstance(rows, list) or not isinstance(rule["where"], dict) \
            or not all(isinstance(s, str) for s in strings):
        raise Fail("rows is not an array, where not an object, or set, key or field not strings")
    if rule["over"] == "numerical":
        methods = doc.get("methods")
        if not isinstance(methods, list) or not all(isinstance(m, dict) for m in methods):
            raise Fail("over is \"numerical\" but methods is not a list of objects")
        allowed = {m.get("name") for m in methods if m.get("exact_flow") is False}
    elif rule["over"] != "all":
        raise Fail("over is %s, not \"numerical\" or \"all\"" % show(rule["over"]))
    found, expected = set(), []
    for i, row in enumerate(rows):
        if not isinstance(row, dict):
            raise Fail("row %d of %s is not an object" % (i, rule["rows"]))
        if not all(f in row and same_json(row[f], v) for f, v in rule["where"].items()):
            continue
        if not isinstance(row.get(key), str):
            raise Fail("row %d has no string %s" % (i, show(key)))
        if rule["over"] == "numerical" and row[key] not in allowed:
            continue
        token = field.replace("~", "~0").replace("/", "~1")  # RFC 6901 escapes
        expected.append((rule["file"], "%s/%d/%s" % (rule["rows"], i, token)))
        if field in row and same_json(row[field], rule["equals"]):
            found.add(row[key])
    problems = []
    if found != set(want):
        problems.append("set is %s, the rows give %s"
                        % (show(sorted(set(want))), show(sorted(found))))
    got = [(e.get("file"), e.get("pointer")) for e in evidence]
    if sorted(got, key=str) != sorted(expected, key=str):
        problems.append("evidence should be one item per row: %d expected, %d given, missing %s, "
                        "extra %s" % (len(expected), len(got), show([p for f, p in expected if
                        (f, p) not in got]), show([p for f, p in got if (f, p) not in expected])))
    return problems

def check_trend(rule, values):
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
    if rule["statistic"] != "spearman":
        raise Fail("unknown statistic %s" % show(rule["statistic"]))
    x, y, d = rule["x"], rule["y"], rule["decimals"]
    if not isinstance(x, list) or not isinstance(y, list) or not x or len(x) != len(y) or not all(
            isinstance(i, int) and not isinstance(i, bool) and 0 <= i < len(values) for i in x + y):
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
    index = lambda k: isinstance(k, int) and not isinstance(k, bool) and 0 <= k < len(values)
    if not isinstance(others, list) or not isinstance(noise, list) \
            or not all(index(k) for k in [i] + others + noise):
        raise Fail("a %s, others %s or noise %s is not an index into the %d evidence values"
                   % (show(i), show(others), show(noise), len(values)))
    if rule["relation"] not in ("less", "tie"):
        raise Fail("relation is %s, not \"less\" or \"tie\"" % show(rule["relation"]))
    if not is_number(m):
        raise Fail("margin is %s, not a number" % show(m))
    x = {k: to_number(values[k], "evidence %d" % k) for k in [i] + others + noise}
    nulls = sorted(k for k, v in x.items() if v is None)
    if nulls:
        raise Fail("evidence %s null (not measured)" % ", ".join(map(str, nulls)))
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
    """Evidence not empty and every value v (+infinity for "unbounded"/"never") has v op limit;
    a null value fails."""
    op, limit = rule["op"], rule["limit"]
    if not isinstance(op, str) or op not in THRESHOLD_OPS:
        raise Fail("op is %s, not one of %s"
                   % (show(op), ", ".join(map(json.dumps, THRESHOLD_OPS))))
    if not is_number(limit):
        raise Fail("limit is %s, not a number" % show(limit))
    if not values:
        raise Fail("the evidence is empty")
    problems = []
    for k, v in enumerate(values):
        x = to_number(v, "evidence %d" % k)
        if x is None:
            problems.append("evidence %d is null (not measured), not %s %s" % (k, op, show(limit)))
        elif not THRESHOLD_OPS[op](x, limit):
            problems.append("evidence %d is %s, not %s %s" % (k, show(x), op, show(limit)))
    return problems

# --- a claim and the file -----------------------------------------------------------------
def check_claim(report, doc, claim):
    if any(f not in claim for f in CLAIM_FIELDS):
        raise Fail("missing fields: %s" % ", ".join(f for f in CLAIM_FIELDS if f not in claim))
    kind, rule, evidence = claim["kind"], claim["rule"], claim["evidence"]
    if kind not in RULE_FIELDS:
        raise Fail("unknown kind %s" % show(kind))
    if not isinstance(rule, dict) or any(f not in rule for f in RULE_FIELDS[kind]):
        raise Fail("rule lacks one of %s" % ", ".join(RULE_FIELDS[kind]))
    if not isinstance(evidence, list) or not all(isinstance(e, dict) for e in evidence):
        raise Fail("evidence is not a list of objects")
    problems, values = [], []
    for k, e in enumerate(evidence):  # every recorded value must still be the file's
        try:
            if any(f not in e for f in ("file", "pointer", "value")):
                raise Fail("lacks file, pointer or value")
            found = resolve(report.file(e["file"]), e["pointer"])
            values.append(found)
            if not same_json(found, e["value"]):
                problems.append("evidence %d (%s %s): recorded %s, the file holds %s"
                                % (k, e["file"], e["pointer"], show(e["value"]), show(found)))
        except Fail as why:
            problems.append("evidence %d: %s" % (k, why))
    try:
        if kind == "membership":
            problems += check_membership(report, doc, rule, evidence)
        elif len(values) == len(evidence):  # the other rules read the evidence's values
            check = {"trend": check_trend, "statistic": check_statistic,
                     "comparison": check_comparison, "threshold": check_threshold}[kind]
            problems += check(rule, values)
    except Fail as why:
        problems.append(str(why))
    return problems

def verify(report_dir):
    """[(label, [problems])] per claim, [] where it holds; BadClaimsFile for exit status 2."""
    path = os.path.join(report_dir, "data", "claims.json")
    try:
        doc = load_json(path)
    except FileNotFoundError:
        raise BadClaimsFile("%s: missing" % path)
    except (OSError, ValueError) as e:
        raise BadClaimsFile("%s: not valid JSON (%s)" % (path, e))
    if not isinstance(doc, dict) or doc.get("schema") != SCHEMA \
            or not isinstance(doc.get("claims"), list):
        raise BadClaimsFile("%s: not a %s document with a claims array" % (path, SCHEMA))
    report, seen, results = Report(report_dir), set(), []
    for i, claim in enumerate(doc["claims"]):
        cid = claim.get("id") if isinstance(claim, dict) else None
        label = cid if isinstance(cid, str) else "claims[%d]" % i
        try:
            if not isinstance(cid, str):  # also a claim that is not an object
                raise Fail("no string id")
            if cid in seen:
                raise Fail("duplicate id")
            seen.add(cid)
            problems = check_claim(report, doc, claim)
        except Fail as why:
            problems = [str(why)]
        except (TypeError, AttributeError, ValueError, KeyError, OverflowError) as e:  # malformed
            problems = ["cannot evaluate the rule (%s)" % e]
        results.append((label, problems))
    return results

def main(argv):
    if len(argv) != 2:
        print("usage: verify_claims.py REPORT_DIR", file=sys.stderr)
        return 2
    try:
        results = verify(argv[1])
    except BadClaimsFile as e:
        print("verify_claims: %s; accepted: a JSON object with \"schema\": \"%s\" and a "
              "\"claims\" array" % (e, SCHEMA), file=sys.stderr)
        return 2
    failed = [(label, p) for label, p in results if p]
    for label, problems in failed:
        print("%s: %s" % (label, "; ".join(problems)))
    print("claims: %d, hold: %d, do not hold: %d"
          % (len(results), len(results) - len(failed), len(failed)))
    return 1 if failed else 0

if __name__ == "__main__":
    sys.exit(main(sys.argv))

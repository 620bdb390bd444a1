"""Numbers with their units for the report: a value and its SI unit become "1.06 mm/s" (a scaled SI
prefix, three significant digits, or as many as an uncertainty resolves), and a check's expected and
measured texts (index.h5's /checks, DESIGN.md "Results") get the unit of the metric they name, read
from the run's /sweep table (each column's `unit` attribute).
"""
import math
import re

PREFIXES = [(1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "µ"), (1e-9, "n")]
# Units a prefix scales linearly: the first factor carries no power ("m^2/s" keeps its unit).
_PREFIXABLE = re.compile(r"^(m|s|N|Hz|J|W|Pa|rad|g)(?=$|[/ (])")
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_NUM = re.compile(r"(?<![A-Za-z0-9_.])" + NUMBER)  # not the 4 of "rk4" nor a name's digits
HUGE = 1e6  # a bound at or past this magnitude is "no bound" (checks write expect = [1, 1e9])


def digits_for(value, uncertainty):
    """Significant digits of `value` whose last one sits at the leading digit of `uncertainty`
    (at least 1, at most 6); 3 when no uncertainty is known."""
    if uncertainty is None or not math.isfinite(uncertainty) or uncertainty <= 0 or value == 0:
        return 3
    return max(1, min(6, int(math.floor(math.log10(abs(value)))) - int(math.floor(math.log10(uncertainty))) + 1))


def digits_to_tell(value, window, digits):
    """At least `digits` significant digits, and as many more (up to 6) as it takes for `value`
    rounded to lie on the same side of each bound of `window` (lo, hi) as `value`: a ratio of 1.0506
    against [0.95, 1.05] reads 1.051, not 1.05."""
    if not window or value == 0 or not math.isfinite(value):
        return digits
    lo, hi = window
    while digits < 6:
        shown = float(f"{value:.{digits - 1}e}")
        if (shown < lo) == (value < lo) and (shown > hi) == (value > hi):
            break
        digits += 1
    return digits


def _plain(v, digits):
    """v with `digits` significant digits (trailing zeros kept: 3.40), without an exponent between
    1e-4 and 1e6; integral values (counts) as they are."""
    if v == int(v) and abs(v) < HUGE:
        return str(int(v))
    mag = math.floor(math.log10(abs(float(f"{v:.{digits - 1}e}"))))
    if -4 <= mag < 6:
        return f"{v:.{max(0, digits - 1 - mag)}f}"
    return f"{v:.{digits - 1}e}".replace("e+0", "e").replace("e-0", "e-").replace("e+", "e")


def prefix_for(values, unit):
    """(scale, prefixed unit) for a group of values sharing one unit: none while the largest
    magnitude is in [0.1, 10^4), else the prefix that puts it in [1, 1000)."""
    m = _PREFIXABLE.match(unit or "")
    finite = [abs(v) for v in values if v is not None and math.isfinite(v) and v != 0]
    if not m or not finite:
        return 1.0, unit or ""
    top = max(finite)
    if 0.1 <= top < 1e4:  # 0.65 Hz, 240 N, 9.19 s read best unprefixed
        return 1.0, unit
    for scale, p in PREFIXES:
        if top >= scale:
            if p == "k" and m.group(1) == "g":  # 1 kg is "1 kg", not a prefix on the kilogram's gram
                break
            return scale, p + unit
    return PREFIXES[-1][0], PREFIXES[-1][1] + unit


def number(v, digits=3):
    """A bare number with `digits` significant digits ("nan", "inf" as such)."""
    if not math.isfinite(v):
        return str(v)
    return _plain(v, digits)


def quantity(value, unit="", uncertainty=None, digits=None):
    """"1.06 mm/s" for (0.00106039, "m/s"): a scaled SI prefix and three significant digits, or the
    digits the uncertainty resolves."""
    d = digits or digits_for(value, uncertainty)
    scale, u = prefix_for([value], unit)
    s = number(value / scale, d)
    return f"{s} {u}" if u else s


def group(values, unit="", digits=3, exact=False):
    """Several values of one unit with one prefix: "30.9, 7.13, 5.11 mm", with more digits (up to
    six) where three would print two different values alike ("1.0001, 1.0004", not "1.00, 1.00").
    exact: the shortest text that keeps each value (a check's typed bounds)."""
    scale, u = prefix_for(values, unit)
    if exact:
        return [_exact(v / scale) for v in values], u
    while True:
        out = [number(v / scale, digits) for v in values]
        alike = any(out[i] == out[j] and values[i] != values[j] for i in range(len(out)) for j in range(i))
        if not alike or digits >= 6:
            return out, u
        digits += 1


def _exact(v):
    """The shortest text of a typed bound: 235.2, 1e-12."""
    return f"{v:.6g}".replace("e+0", "e").replace("e-0", "e-").replace("e+", "e")


def _with_unit(s, u):
    return f"{s} {u}" if u else s


def expected_text(expected, unit, like=()):
    """A check's expected text with its bounds in the metric's unit, scaled by the prefix of the
    measured values `like` when that reads well: "hub_rms_displacement_m in [0.05, 0.06]" ->
    "hub_rms_displacement_m in [50, 60] mm"; an open bound reads "≥ 1"."""
    m = re.match(rf"^(.*\bin )\[({NUMBER}), ({NUMBER})\]$", expected.strip())
    if not m:
        return expected
    lo, hi = float(m.group(2)), float(m.group(3))
    scale, u = prefix_for(list(like), unit)
    if any(v != 0 and not 1e-3 <= abs(v / scale) < 1e3 for v in (lo, hi) if abs(v) < HUGE):
        scale, u = 1.0, unit
    a, b = _exact(lo / scale), _exact(hi / scale)
    if hi >= HUGE and lo > -HUGE:
        return _with_unit(f"{m.group(1).rstrip()[:-3]} ≥ {a}", u)
    return _with_unit(f"{m.group(1)}[{a}, {b}]", u)


_SE = re.compile(rf"(.*?) \+- ({NUMBER}|nan|inf)"
                 rf"(?: \((2 s\.e\.|95%, {NUMBER} dof): \[({NUMBER}), ({NUMBER})\]\)| \((no interval: .*? dof)\))?")
_SE_MOST = re.compile(rf"(.*), standard errors up to ({NUMBER}|nan|inf)")


def with_error(value, se, unit, interval=None, basis="2 s.e."):
    """"1.024 ± 0.012 N": the value to the standard error's second digit, the error to two; the
    runner's interval after it when given, with its basis ("95%, 5 dof", or "2 s.e." from runs
    judged before the Student-t interval), or the basis alone when it has no interval."""
    scale, u = prefix_for([value], unit)
    d = digits_for(value, se) + 1 if math.isfinite(se) and se > 0 else 3
    err = number(se / scale, 2) if math.isfinite(se) else str(se)
    out = _with_unit(f"{number(value / scale, d)} ± {err}", u)
    if interval:
        lo, hi = (number(x / scale, d) for x in interval)
        out += f" ({basis}: " + _with_unit(f"[{lo}, {hi}]", u) + ")"
    elif basis.startswith("no interval"):
        out += f" ({basis})"
    return out


def got_text(got, unit, units, uncertainty=None, window=None):
    """A check's measured text with units: one value, "[lo, hi] over N points", a list (monotonic
    checks), "name=value" pairs whose names are sweep columns (argmax, argmin), each perhaps with the
    runner's standard error ("v +- s (95%, 5 dof: [a, b])", "..., standard errors up to s"). With the
    check's window (lo, hi), one value keeps the digits that put it on its own side of the bounds."""
    g = got.strip()
    m = _SE.fullmatch(g)
    if m and re.fullmatch(NUMBER, m.group(1).strip()):
        interval = (float(m.group(4)), float(m.group(5))) if m.group(4) else None
        return with_error(float(m.group(1)), float(m.group(2)), unit, interval, m.group(3) or m.group(6) or "")
    m = _SE_MOST.fullmatch(g)
    if m:
        most = float(m.group(2))
        return (got_text(m.group(1), unit, units, most if math.isfinite(most) else uncertainty) +
                f", standard errors up to {quantity(most, unit, digits=2) if math.isfinite(most) else most}")
    d = digits_for(_first(g) or 0.0, uncertainty)
    if re.fullmatch(NUMBER, g):
        return quantity(float(g), unit, digits=digits_to_tell(float(g), window, d))
    m = re.fullmatch(rf"\[({NUMBER}), ({NUMBER})\] over (\d+) points", g)
    if m:
        (a, b), u = group([float(m.group(1)), float(m.group(2))], unit, d)
        return _with_unit(f"[{a}, {b}]", u) + f" over {m.group(3)} points"
    m = re.fullmatch(rf"({NUMBER}) over (\d+) points", g)
    if m:
        return f"{quantity(float(m.group(1)), unit, digits=d)} over {m.group(2)} points"
    parts = [p.strip() for p in g.split(",")]
    if len(parts) > 1 and all(re.fullmatch(NUMBER, p) for p in parts):
        vals, u = group([float(p) for p in parts], unit, d)
        return _with_unit(", ".join(vals), u)
    return named_text(g, units)


def named_text(s, units):
    """Every "name=value" or "name value" whose name is a known column gets that column's unit;
    every other number three significant digits."""
    def named(m):
        return f"{m.group(1)}{m.group(2)}{quantity(float(m.group(3)), units.get(m.group(1), ''))}"

    pat = re.compile(rf"\b([A-Za-z_][A-Za-z0-9_]*)(=| )({NUMBER})\b")
    out, pos = [], 0
    for m in pat.finditer(s):
        if m.group(1) not in units:
            continue
        out.append(_bare(s[pos:m.start()]))
        out.append(named(m))
        pos = m.end()
    out.append(_bare(s[pos:]))
    return "".join(out)


def _bare(s):
    return _NUM.sub(lambda m: number(float(m.group(0))) if _is_value(m, s) else m.group(0), s)


def _is_value(m, s):
    """A number in free text, not part of a name (natural_hz_2) or a label."""
    before = s[m.start() - 1] if m.start() > 0 else " "
    return not (before.isalnum() or before == "_")


def _first(s):
    m = _NUM.search(s)
    return float(m.group(0)) if m else None


def numbers(s):
    """Every number of a measured text except "over N points"' count, for comparing two runs."""
    return [v for v, _ in named_numbers(s)]


def named_numbers(s):
    """[(value, the name written just before it as "name=" or "name ", or "")] of a measured text,
    without "over N points"' count."""
    s = re.sub(r" over \d+ points", "", s)
    s = re.sub(r"( \+- |, standard errors up to ).*$", "", s)  # the runner's standard error
    out = []
    for m in _NUM.finditer(s):
        name = re.search(r"([A-Za-z_][A-Za-z0-9_]*)[= ]$", s[:m.start()])
        out.append((float(m.group(0)), name.group(1) if name else ""))
    return out


def unit_of_number(check, units, index):
    """The unit of the index-th number of a check's measured text: its name's column's unit when a
    column name precedes it (argmax's "metric=value"), else the check's own unit."""
    pairs = named_numbers(str(check.get("got", "")))
    if 0 <= index < len(pairs) and pairs[index][1] in units:
        return units[pairs[index][1]]
    return "" if is_dimensionless(check) else units.get(metric_of(check), "")


def metric_of(check):
    """The sweep column a check reads, from its expected text (the runner writes it first:
    "M in [a, b]", "M strictly increasing in AXIS", "M ratio in ...", "order of M in AXIS ...")."""
    e = check.get("expected", "")
    m = re.match(r"^order of (\w+) in", e)
    if m:
        return m.group(1)
    m = re.match(r"^(\w+)\b", e)
    return m.group(1) if m else ""


def is_dimensionless(check):
    """Ratios and observed orders carry no unit, whatever their metric's."""
    e = check.get("expected", "")
    return check.get("type") in ("ratio", "order") or " ratio in " in e or e.startswith("order of ") or " / " in e


def check_texts(check, units, uncertainty=None):
    """(expected, measured) of one check with units; the bounds take the measured values' prefix."""
    unit = "" if is_dimensionless(check) else units.get(metric_of(check), "")
    got = str(check.get("got", ""))
    simple = re.fullmatch(rf"(?:\[)?{NUMBER}(?:, {NUMBER})*(?:\])?(?: over \d+ points)?", got.strip())
    window = re.search(rf" in \[({NUMBER}), ({NUMBER})\]$", str(check.get("expected", "")))
    return (expected_text(str(check.get("expected", "")), unit, numbers(got) if simple else ()),
            got_text(got, unit, units, uncertainty, (float(window.group(1)), float(window.group(2))) if window else None))

"""A refinement study's unrefined cases are its claim's points: for each (study, claim, labels) below, the
parameters that `creaturelab show` resolves for the study's point of each label equal the claim's point of
that label, key by key. A study that builds on another file (flyer3d_flesh_convergence on
flyer3d_convergence) can miss a setting its claim adds, and then refines another configuration than the
one the claim reports.
usage: study_claim.py CREATURELAB [STUDY CLAIM LABEL,LABEL]...  (without pairs: the project's refinement studies)
Exit 0 when every pair agrees; 1 with one line per differing key."""
import re
import subprocess
import sys

PAIRS = [
    ("studies/control/flyer3d_convergence.toml", "experiments/control/flyer3d.toml", ["controlled", "held"]),
    ("studies/control/flyer3d_twist_convergence.toml", "experiments/control/flyer3d_twist.toml", ["controlled", "held"]),
    ("studies/control/flyer3d_flesh_convergence.toml", "experiments/control/flyer3d_flesh.toml", ["controlled", "held"]),
    ("studies/control/swimmer3d_convergence.toml", "experiments/control/swimmer3d.toml", ["controller", "held"]),
]

# key = value [unit], value a quoted string or a bare token
PARAM = re.compile(r'^\s+(?:\* )?([A-Za-z_][A-Za-z0-9_]*) = ("(?:[^"\\]|\\.)*"|\S+)')
POINT = re.compile(r"^\s+point \d+ \((.*)\)$")
# key=value, value a quoted string (commas inside) or a bare token
OVERRIDE = re.compile(r'([A-Za-z_][A-Za-z0-9_]*)=("(?:[^"\\]|\\.)*"|[^,]*)')


def number_or_text(text):
    """A value as show prints it, compared as a number when it is one (2 and 2.0 alike)."""
    text = text.strip()
    try:
        return float(text)
    except ValueError:
        return text.strip('"')


def points(binary, path):
    """{label: {key: value}} of every point of `path`, its resolved parameters with the point's overrides."""
    out = subprocess.run([binary, "show", path], check=True, capture_output=True, text=True).stdout
    base, result, in_params = {}, {}, False
    for line in out.splitlines():
        if line.startswith("parameters (resolved"):
            in_params = True
            continue
        if in_params:
            if not line.strip():
                in_params = False
                continue
            m = PARAM.match(line)
            if m:
                base[m.group(1)] = number_or_text(m.group(2))
            continue
        m = POINT.match(line)
        if not m:
            continue
        body = m.group(1)
        first = OVERRIDE.search(body)
        label = body[: first.start()].rstrip(", ") if first else body
        params = dict(base)
        if first:
            for key, value in OVERRIDE.findall(body[first.start():]):
                params[key] = number_or_text(value)
        params.pop("label", None)
        result[label] = params
    return result


def differences(binary, study, claim, labels):
    study_points, claim_points = points(binary, study), points(binary, claim)
    lines = []
    for label in labels:
        if label not in study_points or label not in claim_points:
            lines.append(f"{study}: no point labelled {label!r} in it or in {claim}")
            continue
        s, c = study_points[label], claim_points[label]
        for key in sorted(set(s) | set(c)):
            if s.get(key) != c.get(key):
                lines.append(f"{study} '{label}': {key} = {s.get(key)!r}, {claim} has {c.get(key)!r}")
    return lines


def main(argv):
    binary, rest = argv[1], argv[2:]
    pairs = [(rest[i], rest[i + 1], rest[i + 2].split(",")) for i in range(0, len(rest), 3)] if rest else PAIRS
    lines = [line for study, claim, labels in pairs for line in differences(binary, study, claim, labels)]
    for line in lines:
        print(line)
    return 1 if lines else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

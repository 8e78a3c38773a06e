#!/usr/bin/env python3
"""Checks each number docs/findings.md quotes from a table against that table.

Usage: check-findings.py FINDINGS RESULTS_DIR

A quoted number is followed, in the same paragraph, by a check in an HTML comment (invisible
when the page is rendered):

    <!-- check TABLE | COLUMN | KEY=VALUE; KEY=VALUE | AGGREGATE | QUOTED [xSCALE] -->

TABLE is a CSV under RESULTS_DIR (the main job's `out/`: stability/..., refine/..., sweep/...,
suite/SCENE/engine_metrics.csv); the rows are those whose KEY columns equal VALUE (numbers
compared to 1e-4 relative, so a step written 0.0166667 finds 0.01666666667; a scene path by its
name, so scene=cloth_hanging finds scenes/matched/cloth_hanging.json); AGGREGATE is `one`
(exactly one row), `min` or `max` over them, or `ratio KEY=A/B`: the value of the one row with
KEY=A over that of the one row with KEY=B (an error's ratio per halving of the step), or
`relative to OTHER`: (COLUMN - OTHER) / OTHER of the one row (a value against its reference). QUOTED is the number as the text writes it, and
must appear in the 400 characters before the comment; the table's value times SCALE (100 for a
percentage) must round to it: within half a unit of its last digit. So a finding states a
number only as precisely as the table holds it, and a table that moves makes the check fail.

Exits 0 when every check holds, 1 naming each that does not (and a findings file with no
checks), 2 on a malformed check.
"""
import csv
import math
import re
import sys
from pathlib import Path

CHECK = re.compile(r"<!--\s*check\s+(.*?)\s*-->", re.S)


def as_number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def matches(cell, wanted):
    a, b = as_number(cell), as_number(wanted)
    if a is not None and b is not None:
        return math.isclose(a, b, rel_tol=1e-4, abs_tol=1e-300)
    return cell == wanted or Path(cell).stem == wanted  # a scene by its name, wherever it was run from


def half_unit(quoted):
    """Half a unit of the quoted number's last digit: 0.59 -> 0.005, 1.7e-5 -> 5e-7, 620 -> 0.5."""
    mantissa, _, exponent = quoted.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10 ** (-decimals) * 10 ** (int(exponent) if exponent else 0)


def parse(body):
    parts = [p.strip() for p in body.split("|")]
    if len(parts) != 5:
        raise ValueError(f"expected 'TABLE | COLUMN | FILTERS | AGGREGATE | QUOTED', got '{body}'")
    table, column, filters, aggregate, quoted = parts
    wanted = {}
    for item in filter(None, (f.strip() for f in filters.split(";"))):
        key, sep, value = item.partition("=")
        if not sep:
            raise ValueError(f"filter '{item}' is not KEY=VALUE")
        wanted[key.strip()] = value.strip()
    if aggregate not in ("one", "min", "max") and not re.fullmatch(r"ratio \S+=[^/\s]+/[^/\s]+", aggregate) \
            and not re.fullmatch(r"relative to \S+", aggregate):
        raise ValueError(f"aggregate '{aggregate}' is not one, min, max, ratio KEY=A/B or relative to OTHER")
    number, _, scale = quoted.partition(" x")
    if as_number(number) is None or (scale and as_number(scale) is None):
        raise ValueError(f"quoted '{quoted}' is not NUMBER or NUMBER xSCALE")
    return table, column, wanted, aggregate, number, float(scale or 1)


def measured(results, table, column, wanted, aggregate):
    if aggregate.startswith("ratio "):
        key, _, pair = aggregate[6:].partition("=")
        top, bottom = pair.split("/")
        a, problem = measured(results, table, column, {**wanted, key: top}, "one")
        if problem:
            return None, problem
        b, problem = measured(results, table, column, {**wanted, key: bottom}, "one")
        if problem or b == 0:
            return None, problem or f"{table}: the ratio's denominator is 0"
        return a / b, None
    if aggregate.startswith("relative to "):
        value, problem = measured_rows(results, table, column, wanted, "one")
        reference, other_problem = measured_rows(results, table, aggregate[12:], wanted, "one")
        if problem or other_problem or reference == 0:
            return None, problem or other_problem or f"{table}: the reference is 0"
        return (value - reference) / reference, None
    return measured_rows(results, table, column, wanted, aggregate)


def measured_rows(results, table, column, wanted, aggregate):
    path = results / table
    if not path.is_file():
        return None, f"no table {path}"
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if rows and column not in rows[0]:
        return None, f"{table} has no column '{column}'"
    chosen = [r for r in rows if all(k in r and matches(r[k], v) for k, v in wanted.items())]
    values = [as_number(r[column]) for r in chosen]
    if not chosen or any(v is None for v in values):
        return None, f"{table}: {len(chosen)} rows match, not all with a number in '{column}'"
    if aggregate == "one" and len(values) != 1:
        return None, f"{table}: {len(values)} rows match where the check expects one"
    return (min(values) if aggregate == "min" else max(values) if aggregate == "max" else values[0]), None


def check(text, results):
    """(checks made, failures): each failure a line naming the check and what the table says."""
    failures, count = [], 0
    for m in CHECK.finditer(text):
        count += 1
        line = text.count("\n", 0, m.start()) + 1
        table, column, wanted, aggregate, quoted, scale = parse(m.group(1))
        before = text[max(0, m.start() - 400):m.start()]
        if quoted not in before:
            failures.append(f"line {line}: the text before the check does not quote {quoted}")
            continue
        value, problem = measured(results, table, column, wanted, aggregate)
        if problem:
            failures.append(f"line {line}: {problem}")
        elif abs(value * scale - float(quoted)) > half_unit(quoted) * (1 + 1e-9):
            failures.append(f"line {line}: quotes {quoted}, the table says {value * scale:.6g} "
                            f"({table}, {column}, {aggregate} of {wanted})")
    return count, failures


def main():
    if len(sys.argv) != 3:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    findings, results = Path(sys.argv[1]), Path(sys.argv[2])
    try:
        count, failures = check(findings.read_text(), results)
    except ValueError as e:
        print(f"{findings}: malformed check: {e}", file=sys.stderr)
        return 2
    for f in failures:
        print(f"{findings}: {f}")
    if count == 0:
        print(f"{findings}: no checks: nothing it quotes is held to a table")
        return 1
    print(f"{findings}: {count - len(failures)} of {count} quoted numbers match their tables")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

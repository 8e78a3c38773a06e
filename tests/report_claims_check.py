#!/usr/bin/env python3
"""Holds what the report drew to the evidence rule (issue 37): a Richardson limit or an order is
drawn only from four or more resolutions, or from three whose observed order agrees with the
discretisation's expected one within 30 % (compare/studies/refinement.h, kOrderAgreement).
Reads claims.json, which make_report.py writes beside the report: one entry per limit drawn.
Usage: report_claims_check.py CLAIMS_JSON; exit 1 naming each claim without the evidence."""
import json
import sys

AGREEMENT = 0.3  # kOrderAgreement


def evidenced(claim):
    resolutions = claim["resolutions"].split()
    if len(resolutions) >= 4:
        return True
    if len(resolutions) < 3 or not claim.get("expected_order") or not claim.get("observed_order"):
        return False
    observed, expected = float(claim["observed_order"]), float(claim["expected_order"])
    return abs(observed - expected) <= AGREEMENT * max(observed, expected)


def main(path):
    with open(path) as f:
        claims = json.load(f)
    bad = [c for c in claims if not evidenced(c) or not c.get("verdict", "").startswith("converged")]
    for c in bad:
        print(f"FAIL: page {c['page']} draws a {c['kind']} of {c['quantity']} ({c['engine']}) from "
              f"resolutions {c['resolutions'] or 'none'}, observed order {c['observed_order'] or 'none'}, "
              f"expected {c['expected_order'] or 'none'}: not the evidence a limit needs")
    print(f"report claims: {len(claims)} limits drawn, {len(bad)} without evidence")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

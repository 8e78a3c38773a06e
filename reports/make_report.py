#!/usr/bin/env python3
"""Draws the springcheck report (report.pdf and one PNG per page) from a manifest.

`springcheck report` writes the manifest (compare/io/include/compare/io/report_manifest.h): which result
tables exist, the scenes and engines in them, and for each missing input the command that makes
it. This script reads only what the manifest names and only draws: every number comes from the
C++ side. A missing input is a page naming its command, never a traceback.

Run with the interpreter that has matplotlib (CMake finds it; `springcheck report` uses it).
"""
import argparse
import json
import os
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.backends.backend_pdf import PdfPages  # noqa: E402

import report_pages  # noqa: E402
from report_style import PAGE_SIZE, StyleTable  # noqa: E402


class Context:
    """What every page may read: the manifest, the style table, and the page numbers (so the
    dashboard can say where each headline comes from)."""

    def __init__(self, manifest):
        self.manifest = manifest
        names = [e["name"] for c in manifest["comparisons"] for e in c["engines"]]
        self.styles = StyleTable(manifest.get("series", []), (n for n in names if not n.startswith("mysim")))
        self.numbers = {}
        # What pages drew that the data must carry (a Richardson limit, an order): written beside
        # the report as claims.json, where a test holds each to the evidence rule.
        self.claims = []

    def page_of(self, key):
        number = self.numbers.get(key)
        return f"p. {number}" if number else "no page"


def draw_title(fig, title):
    """The page's answer: one line of 14-point bold holds about 100 characters of the A4 width (up
    to 120 in smaller type); a longer one goes on two lines of smaller type (never cut at the
    edges, clear of the command)."""
    if len(title) <= 120:
        fig.text(0.5, 0.955, title, ha="center", va="center", fontsize=min(14, 14 * 100 / len(title)),
                 weight="bold")
        return
    lines = textwrap.wrap(title, max(len(title) // 2 + 10, 60), break_on_hyphens=False)
    size = min(12, 12 * 118 / max(len(line) for line in lines))
    fig.text(0.5, 0.963, "\n".join(lines), ha="center", va="center", fontsize=size, weight="bold",
             linespacing=1.1)


def frame(fig, page, number, total, stamp, notes):
    """Title (the question the page answers), caption (how to read it), page number and stamp."""
    draw_title(fig, page.title)
    caption = " ".join([page.caption] + list(notes or []))
    lines = textwrap.wrap(caption, 165)
    # A long caption (many notes) in smaller type, above the stamp: 200 characters of 7-point type
    # fill the width 165 of 8.5-point do. (The type follows the first wrap: rewrapped at 200, a
    # six-line caption became five lines and was drawn at 8.5 points, cut at the right edge.)
    small = len(lines) > 5
    if small:
        lines = textwrap.wrap(caption, 200)
    fig.text(0.06, 0.155, "\n".join(lines), va="top", fontsize=7 if small else 8.5, color="0.15")
    if page.command:  # under the title: the page's own command, apart from the caption's text
        # A long one (refine over several scenes) in two lines of smaller type, never cut at the edges.
        command = f"reproduce: {page.command}"
        lines = textwrap.wrap(command, 190, break_on_hyphens=False) if len(command) > 150 else [command]
        fig.text(0.5, 0.925, "\n".join(lines[:2]) + (" ..." if len(lines) > 2 else ""), ha="center",
                 va="center", fontsize=7 if len(lines) == 1 else 6, family="monospace", color="0.3")
    fig.text(0.06, 0.02, f"springcheck {stamp['version']} (commit {stamp['commit']})  ·  "
             f"{stamp['date']}  ·  {stamp['machine']}\n{stamp['command']}", fontsize=7, color="0.4",
             va="bottom")
    fig.text(0.97, 0.02, f"page {number} of {total}", ha="right", va="bottom", fontsize=8, color="0.3")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--manifest", required=True, help="manifest.json from springcheck report")
    parser.add_argument("--out", required=True, help="where report.pdf and the PNGs go")
    args = parser.parse_args()
    with open(args.manifest) as f:
        manifest = json.load(f)
    ctx = Context(manifest)
    pages = report_pages.pages(ctx)
    ctx.numbers = {page.key: i + 1 for i, page in enumerate(pages)}
    os.makedirs(args.out, exist_ok=True)
    for old in os.listdir(args.out):  # a PNG of an earlier report with more pages must not stay
        if old.endswith(".png"):
            os.remove(os.path.join(args.out, old))
    pdf_path = os.path.join(args.out, "report.pdf")
    tmp_path = pdf_path + ".part"
    with PdfPages(tmp_path) as pdf:
        for i, page in enumerate(pages):
            fig = plt.figure(figsize=PAGE_SIZE)
            notes = page.draw(fig, ctx)
            frame(fig, page, i + 1, len(pages), manifest["stamp"], notes)
            fig.savefig(os.path.join(args.out, f"{i + 1:02d}_{page.key}.png"), dpi=100)
            pdf.savefig(fig)
            plt.close(fig)
    os.replace(tmp_path, pdf_path)  # whole or not at all
    with open(os.path.join(args.out, "claims.json"), "w") as f:
        json.dump(ctx.claims, f, indent=1)
    # Each page's key and title (its answer), in order: what a reader sees first, listed for a
    # review or a test without opening the PDF.
    with open(os.path.join(args.out, "pages.json"), "w") as f:
        json.dump([{"page": i + 1, "key": p.key, "title": p.title} for i, p in enumerate(pages)], f, indent=1)
    print(f"report: {pdf_path} and {len(pages)} PNGs in {args.out}")


if __name__ == "__main__":
    main()

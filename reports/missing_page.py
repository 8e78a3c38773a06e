"""The page that lists inputs the report did not find, with the command that makes each."""
import textwrap

from report_style import Page


def page(missing):
    def draw(fig, ctx):
        y = 0.88
        for i, m in enumerate(missing):
            lines = textwrap.wrap(m["command"], 150)
            if y - 0.03 - 0.022 * len(lines) < 0.19:
                fig.text(0.06, y, f"... and {len(missing) - i} more: see manifest.json beside this report",
                         fontsize=9)
                break
            fig.text(0.06, y, f"{m['input']}  (for: {m['pages']})", fontsize=9, weight="bold")
            y -= 0.028
            for line in lines:
                fig.text(0.08, y, line, fontsize=8, family="monospace")
                y -= 0.022
            y -= 0.01
        return []
    what = ", ".join(sorted({m["pages"] for m in missing}))
    return Page("missing_inputs", f"{len(missing)} input{'s' if len(missing) != 1 else ''} missing, so these pages "
                f"are left out: {what} (the command that makes each below)",
                "These tables were not in the results folder, so their pages are left out. Run each "
                "command (from any folder; paths as given), then `springcheck report` again. The main job, "
                "scripts/run-suite.sh, makes every one of them but the benchmarks (scripts/run-bench.sh: "
                "minutes of timed runs, kept out of the main job).", draw)

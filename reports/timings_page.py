"""What the main job spent its time on (scripts/run-suite.sh's out/timings.json)."""
import json

from report_style import Page, plot_area


def page(timings_json):
    with open(timings_json) as f:
        data = json.load(f)
    stages = data["stages"]
    total = data["total_seconds"]
    machine = data.get("machine", {})
    stream = machine.get("stream_triad_bytes_per_second")
    where = f"{machine.get('cores', '?')} cores" + (
        f", STREAM triad {stream / 1e9:.1f} GB/s" if stream else "")
    heaviest = max(stages, key=lambda s: s["seconds"]) if stages else None

    def draw(fig, ctx):
        grid = plot_area(fig, 1, 1, left=0.22)
        ax = fig.add_subplot(grid[0, 0])
        names = [s["name"] for s in stages][::-1]
        seconds = [s["seconds"] for s in stages][::-1]
        ax.barh(names, seconds, color="#4c72b0")
        work = [s for s in stages][::-1]
        for y, (v, s) in enumerate(zip(seconds, work)):
            counts = f", {s['runs']} runs, {s['steps']:.2g} steps" if "runs" in s and s["runs"] else ""
            ax.text(v, y, f" {v:.0f} s ({100 * v / total:.0f} %){counts}", va="center", fontsize=7)
        ax.set_xlabel("wall time [s], one run of each stage")
        ax.set_xlim(0, max(seconds) * 1.8 if seconds else 1)
        ax.grid(True, axis="x", alpha=0.3)
        return []

    title = (f"Main job: {total:.0f} s after its build"
             + (f"; longest stage {heaviest['name']} ({heaviest['seconds']:.0f} s)" if heaviest else ""))
    caption = (f"On {where}. Each stage of scripts/main-job.sh (what scripts/run-suite.sh runs after its build), timed as it ran, in order from the top; the total also "
               "counts the STREAM probe. This report, drawn after the table was written, adds its own time, "
               "which the job prints at its end and writes to out/timings.json. Beside each bar: the stage's work "
               "(simulation runs and their steps), which scripts/check-main-job-work.py holds to its record. "
               "Stages whose times a page draws (the sweeps, the trade) time each run alone; the suite, the "
               "stability maps and refine run side by side on every core.")
    return Page("timings", title, caption, draw)

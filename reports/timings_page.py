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
        for y, v in enumerate(seconds):
            ax.text(v, y, f" {v:.0f} s ({100 * v / total:.0f} %)", va="center", fontsize=7)
        ax.set_xlabel("wall time [s], one run of each stage")
        ax.set_xlim(0, max(seconds) * 1.3 if seconds else 1)
        ax.grid(True, axis="x", alpha=0.3)
        return []

    title = (f"Main job: {total:.0f} s after its build"
             + (f"; longest stage {heaviest['name']} ({heaviest['seconds']:.0f} s)" if heaviest else ""))
    caption = (f"On {where}. Each stage of scripts/run-suite.sh, timed as it ran, in order from the top; the total also "
               "counts the STREAM probe. This report, drawn after the table was written, adds its own time, "
               "which the job prints at its end and writes to out/timings.json. Stages that time runs (the "
               "suite, the sweeps) ran alone.")
    return Page("timings", title, caption, draw)

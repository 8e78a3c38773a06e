"""What a step costs (scripts/run-bench.sh's Google Benchmark results)."""
import json

from report_style import Page, plot_area


def page(bench_json):
    def draw(fig, ctx):
        with open(bench_json) as f:
            data = json.load(f)
        median = {}
        for b in data["benchmarks"]:
            if b.get("aggregate_name", "median") == "median":
                median[b.get("run_name", b["name"]).replace("/real_time", "")] = b
        grid = plot_area(fig, 1, 2, wspace=0.35)
        bars, curve = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])
        names, times, colours = [], [], []
        for key, b in median.items():
            for prefix, engine in (("BM_MysimStep/", None), ("BM_BulletStep/", "")):
                if key.startswith(prefix):
                    name = key.split("/")[1]
                    names.append(name)
                    times.append(b["real_time"])
                    style_key = f"mysim:{name}" if engine is None else name
                    colours.append(ctx.styles.of(style_key)[0])
        bars.barh(names, times, color=colours)
        bars.set_xscale("log")
        bars.set_xlabel("time per step, 32 x 32 cloth [us], median of repeats")
        bars.set_title("one step, same scene and dt", fontsize=10)
        bars.grid(True, axis="x", which="both", alpha=0.3)
        sizes, per, bound = [], [], []
        for key, b in median.items():
            if key.startswith("BM_ClothForce/"):
                n = int(key.split("/")[1]) ** 2
                sizes.append(n)
                per.append(b["ns_per_particle"])
                bound.append(b["bound_ns"] / n)
        if sizes:
            curve.loglog(sizes, per, "o-", color="#1f77b4", label="measured (all cores)")
            curve.loglog(sizes, bound, "--", color="black", label="memory-bandwidth bound")
            curve.legend(fontsize=8)
        curve.set_xlabel("particles")
        curve.set_ylabel("force evaluation per particle [ns]")
        curve.set_title("cloth force evaluation against the roofline", fontsize=10)
        curve.grid(True, which="both", alpha=0.3)
        return []
    return Page("performance", "What does a step cost in each engine and integrator?",
                "Left: wall time of one step of the same 32 x 32 cloth at the same dt, median of repeats "
                "(colours as on every page). Right: one force evaluation per particle against the time the "
                "memory traffic alone needs: the closer, the less there is left to gain.", draw)

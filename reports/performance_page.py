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
        # Left margin for the engine names on the bars' axis.
        grid = plot_area(fig, 1, 3, left=0.13, wspace=0.35)
        bars, curve, implicit = (fig.add_subplot(grid[0, k]) for k in range(3))
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
        # Backward Euler at h = 1/60 s, one core: time per step per preconditioner, each point
        # labelled with its CG iterations per step.
        lines = {}
        for key, b in median.items():
            parts = key.split("/")
            if key.startswith("BM_LargeImplicitStep/60/"):
                lines.setdefault(parts[3], []).append(
                    (int(parts[2]) ** 2, b["real_time"], b["cg_iterations_per_step"]))
        for name, colour in (("ssor", "#d62728"), ("block-jacobi", "#1f77b4"), ("jacobi", "#7f7f7f")):
            points = sorted(lines.get(name, []))
            if not points:
                continue
            implicit.loglog([p[0] for p in points], [p[1] for p in points], "o-", color=colour,
                            label=name)
            for n, t, iterations in points:
                implicit.annotate(f"{iterations:.0f}", (n, t), textcoords="offset points",
                                  xytext=(4, -10), fontsize=7, color=colour)
        if lines:
            implicit.legend(fontsize=8, title="CG preconditioner", title_fontsize=8)
        implicit.set_xlabel("particles")
        implicit.set_ylabel("time per step, one core [ms]")
        implicit.set_title("backward Euler at h = 1/60 s", fontsize=10)
        implicit.grid(True, which="both", alpha=0.3)
        return []
    return Page("performance", "What does a step cost in each engine and integrator?",
                "Left: wall time of one step of the same 32 x 32 cloth at the same dt, median of repeats "
                "(colours as on every page). Middle: one force evaluation per particle against the time the "
                "memory traffic alone needs: the closer, the less there is left to gain. Right: one backward Euler "
                "step far above the explicit limit per CG preconditioner, numbers are CG iterations per step "
                "(docs/performance.md).", draw)

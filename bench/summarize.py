#!/usr/bin/env python3
"""Turns the benchmark JSON (medians of repeated runs) and the memory probe into the table of
docs/performance.md: the figures, the mysim / Bullet ratios and each goal met or not. Reads
numbers, computes ratios between them; no physics."""
import csv
import json
import sys


def main(bench_json, memory_json, baseline_json, out_csv, *equal_accuracy):
    runs = {}
    data = json.load(open(bench_json))
    for b in data["benchmarks"]:
        if b.get("aggregate_name", "median") != "median":
            continue
        name = b["run_name"] if "run_name" in b else b["name"]
        for suffix in ("/real_time", "/manual_time", "/iterations:20", "/iterations:3"):
            name = name.replace(suffix, "")
        runs[name] = b
    rows = []

    def add(what, value, unit, goal=""):
        rows.append((what, value, unit, goal))
        print(f"{what:58s} {value:>12.4g} {unit:10s} {goal}")

    ctx = data["context"]
    print(f"machine: {ctx.get('host_name', '?')}, {ctx['num_cpus']} cpus @ {ctx['mhz_per_cpu']} MHz, "
          f"caches {[c['size'] for c in ctx['caches']]}; {ctx['date']}")
    bw = runs["BM_StreamTriad"]["bytes_per_second"]
    add("memory bandwidth (STREAM triad, 2 threads)", bw / 1e9, "GB/s")
    for n in (16, 32, 64, 128, 256):
        r = runs[f"BM_ClothForce/{n}"]
        add(f"force evaluation {n}x{n}: time per particle", r["ns_per_particle"], "ns")
        add(f"force evaluation {n}x{n}: bytes moved per evaluation", r["bytes_per_eval"], "B")
        goal = ("goal <= 2: " + ("met" if r["ratio_to_bound"] <= 2 else "missed")) if n in (128, 256) else ""
        add(f"force evaluation {n}x{n}: measured / bandwidth bound", r["ratio_to_bound"], "x", goal)
    for n in (128, 256):
        fast = runs[f"BM_ClothForce/{n}"]["real_time"]
        add(f"force evaluation {n}x{n}: baseline (no AVX2) kernel / AVX2",
            runs[f"BM_ClothForceBaseline/{n}"]["real_time"] / fast, "x")
        add(f"force evaluation {n}x{n}: per-end reference loop / every spring once",
            runs[f"BM_ClothForceReference/{n}"]["real_time"] / fast, "x")
    one = runs["BM_ClothForceOneThread/256"]["real_time"]
    two = runs["BM_ClothForce/256"]["real_time"]
    add("force evaluation 256x256: 2 threads over 1", one / two, "x")
    # Every integrator and engine the benchmark registered (from the catalogues), in its order.
    for key in runs:
        if key.startswith("BM_MysimStep/") and key.endswith("/32"):
            add(f"mysim {key.split('/')[1]} step, 32x32", runs[key]["real_time"], "us")
    for key in runs:
        if key.startswith("BM_BulletStep/") and key.endswith("/32"):
            add(f"{key.split('/')[1]} step, 32x32", runs[key]["real_time"], "us")
    se = runs["BM_MysimStep/symplectic-euler/32"]["real_time"]
    de = runs["BM_BulletStep/bullet-deformable/32"]["real_time"]
    ratio = de / se
    add("bullet-deformable / mysim symplectic-euler per step", ratio, "x",
        "goal >= 10: " + ("met" if ratio >= 10 else "missed"))
    be = runs["BM_MysimStep/backward-euler/32"]["real_time"]
    bi = runs["BM_BulletStep/bullet-implicit/32"]["real_time"]
    ratio = bi / be
    add("bullet-implicit / mysim backward-euler per step (CG tol 1e-4)", ratio, "x",
        "goal >= 3: " + ("met" if ratio >= 3 else "missed"))
    for integrator in ("symplectic-euler", "rk4"):
        per = [runs[f"BM_MysimStepScaling/{integrator}/{n}"]["ns_per_particle"] * 1e9 for n in (32, 64, 128, 256)]
        for n, p in zip((32, 64, 128, 256), per):
            add(f"{integrator} step per particle, {n}x{n}", p, "ns")
        spread = max(per) / min(per)
        add(f"{integrator}: max/min time per particle, 32..256", spread, "x",
            "goal < 1.5: " + ("met" if spread < 1.5 else "missed"))
    for n in (16, 32, 64, 128):
        r = runs[f"BM_BackwardEulerScaling/{n}"]
        add(f"backward-euler step {n}x{n}", r["real_time"], "us")
        add(f"backward-euler CG iterations per step {n}x{n}", r["cg_iterations_per_step"], "")
    iterations = {}
    for per_second in (60, 240):
        for n in (32, 64, 128, 256):
            for pre in ("ssor", "block-jacobi", "jacobi"):
                if pre == "jacobi" and n > 128:  # not run: seconds a step, nothing new
                    continue
                r = runs[f"BM_LargeImplicitStep/{per_second}/{n}/{pre}"]
                iterations[(per_second, n, pre)] = r["cg_iterations_per_step"]
                goal = ""
                if per_second == 60 and n == 128 and pre == "ssor":
                    goal = "goal < 10 ms: " + ("met" if r["real_time"] < 10 else "missed")
                add(f"backward-euler h = 1/{per_second} s, {n}x{n}, {pre}, 1 thread: step", r["real_time"], "ms", goal)
                add(f"backward-euler h = 1/{per_second} s, {n}x{n}, {pre}: CG iterations per step",
                    r["cg_iterations_per_step"], "")
        # Growth with size: 4x the particles per row; sqrt(N) growth is 2x per row.
        growth = max(iterations[(per_second, 2 * n, "ssor")] / iterations[(per_second, n, "ssor")]
                     for n in (32, 64, 128))
        add(f"backward-euler h = 1/{per_second} s: CG iterations, largest growth per 4x particles", growth, "x",
            "goal <= 2 (sqrt N): " + ("met" if growth <= 2.05 else "missed"))
    t1 = runs["BM_Rk4Threads/256/1"]["real_time"]
    t2 = runs["BM_Rk4Threads/256/2"]["real_time"]
    add("RK4 step 256x256: 1 thread over 2", t1 / t2, "x", "goal >= 1.6: " + ("met" if t1 / t2 >= 1.6 else "missed"))
    load = {c: runs[f"BM_ClothRk4UnderLoad/64/{c}"]["real_time"] for c in
            ("idle_one_thread", "idle_all_threads", "loaded_follow_load", "loaded_fixed_all_threads")}
    for case, t in load.items():
        add(f"RK4 run 64x64 (0.2 s), {case.replace('_', ' ')}", t, "ms")
    ratio = load["loaded_follow_load"] / load["idle_one_thread"]
    add("RK4 64x64 with one busy process / idle one thread", ratio, "x",
        "goal <= 1.3: " + ("met" if ratio <= 1.3 else "missed"))
    mem = json.load(open(memory_json))
    base = json.load(open(baseline_json))
    total = mem["peak_resident_bytes"] / mem["particles"]
    add("peak memory per particle, 256x256 RK4 (whole process)", total, "B",
        "goal < 1024: " + ("met" if total < 1024 else "missed"))
    add("  of which above the process baseline (a 1-particle run)",
        (mem["peak_resident_bytes"] - base["peak_resident_bytes"]) / mem["particles"], "B")
    for path in equal_accuracy:  # springcheck recommend --json on a scene: each engine's best
        answer = json.load(open(path))
        for r in answer["recommendations"]:
            scene = r["scene"].rsplit("/", 1)[-1].removesuffix(".json")
            for c in r.get("per_engine", []):
                add(f"{scene}, error <= {answer['max_error']:g} m: {c['engine']} best "
                    f"({c['integrator']}, dt {c['dt']:g}) realtime factor", c["realtime_factor"], "x")
            ratio = r.get("mysim_over_bullet_realtime")
            if ratio is not None:
                add(f"{scene}: mysim's best / Bullet's best realtime factor at equal accuracy", ratio, "x",
                    "goal >= 10: " + ("met" if ratio >= 10 else "missed"))
    with open(out_csv, "w", newline="") as f:  # quoted: quantities hold commas
        writer = csv.writer(f)
        writer.writerow(["quantity", "value", "unit", "goal"])
        for r in rows:
            writer.writerow([r[0], f"{r[1]:.6g}", r[2], r[3]])


if __name__ == "__main__":
    main(*sys.argv[1:])

"""The command that made each page's table, printed on the page ("reproduce: ..."): read from what
springcheck recorded beside its results (comparison.json's "command", TABLE.command beside a
sweep's or a stability map's table, through the manifest), never guessed."""
import json


def commands(m):
    """page key -> the command that made its table."""
    found = {"dashboard": "scripts/run-suite.sh   (the main job: every table below, then this report)",
             "performance": "scripts/run-bench.sh",
             "timings": "scripts/run-suite.sh   (it times each stage: out/timings.json)"}
    suite = next((c["command"] for c in m["comparisons"] if c["group"] == "suite" and c.get("command")), None)
    for key in ("verdicts", "sag_1", "sag_2", "sag_3", "penetration_1", "penetration_2"):
        if suite:
            found[key] = suite
    if m.get("gate"):
        with open(m["gate"]) as f:
            tolerances = json.load(f).get("tolerances")
        for n in range(1, 20):
            found[f"gates_{n}"] = f"springcheck gate --tolerances {tolerances} --json {m['gate']}"
    for s in m["sweeps"]:
        for prefix in ("speed_accuracy", "convergence", "solver_families"):
            if s.get("command"):
                found[f"{prefix}_{s['name']}"] = s["command"]
    stability = m["stability"]
    for key in ("oscillator", "extremes"):
        if stability.get("stability_command"):
            found[f"stability_{key}"] = stability["stability_command"]
    for entry in stability["scenes"]:
        if entry.get("command"):
            found[f"stability_{entry['scene']}"] = entry["command"]
    for c in m["comparisons"]:
        if c.get("command"):
            group = c["group"].replace("/", "_")
            found[f"drape_{group}_{c['scene']}"] = c["command"]
            found[f"energy_{group}_{c['scene']}"] = c["command"]
    return found


def attach(pages, m):
    known = commands(m)
    for page in pages:
        if page.command is None:
            page.command = known.get(page.key)
    return pages

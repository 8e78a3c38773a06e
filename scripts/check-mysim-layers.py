#!/usr/bin/env python3
"""mysim's include graph against its layer order (docs/architecture.md "Inside mysim").

Usage: check-mysim-layers.py [SOURCE_DIR]. mysim/src/ is cut into folders, one per concept, in
the order LAYERS gives, from the bottom up: a file may include headers of its own layer and of
those below it, never above. A file's layer is its folder under mysim/src/; a public header
(mysim/include/mysim/X.h) is in the layer of its source X.cpp, or, for a header with no source of
its own, in the layer HEADER_ONLY names (a new header-only header must be named there: the check
refuses to guess). Prints every include against the order and the graph's size; exits 1 if any.
"""
import pathlib
import re
import sys

LAYERS = ["core", "forces", "colliders", "model", "solvers", "collision", "systems",
          "integrators", "run", "scene"]

# Public headers with no source file of their own: the contract every layer shares (core), and
# the spring list, which holds springs (forces), and what a collider shape answers (colliders).
HEADER_ONLY = {
    "types.h": "core", "state.h": "core", "ode_system.h": "core", "stepper.h": "core",
    "integrator.h": "core", "blowup.h": "core", "material.h": "core", "limit_error.h": "core",
    "energy_terms.h": "core", "spring_list.h": "forces", "collider_surface.h": "colliders",
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def layer_of_header(name, mysim, problems):
    """The layer of a header as it is included: "mysim/X.h" (public) or "FOLDER/X.h" (internal)."""
    folder, _, file = name.rpartition("/")
    if folder == "mysim":
        sources = sorted((mysim / "src").rglob(pathlib.Path(file).stem + ".cpp"))
        if sources:
            return sources[0].parent.name
        if file in HEADER_ONLY:
            return HEADER_ONLY[file]
        problems.append(f"mysim/include/mysim/{file}: no source of its own and no layer in "
                        "HEADER_ONLY (scripts/check-mysim-layers.py): say which layer it is in")
        return None
    return folder if folder in LAYERS else None


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    mysim = root / "mysim"
    problems, edges = [], 0
    files = sorted((mysim / "src").rglob("*.[ch]*")) + sorted((mysim / "include/mysim").glob("*.h"))
    for path in files:
        if path.parent.name == "mysim":
            own = layer_of_header("mysim/" + path.name, mysim, problems)
        else:
            own = path.parent.name
            if own not in LAYERS:
                problems.append(f"{path.relative_to(root)}: folder '{own}' is not a layer "
                                "(LAYERS in scripts/check-mysim-layers.py)")
                continue
        if own is None:
            continue
        for included in INCLUDE.findall(path.read_text()):
            target = layer_of_header(included, mysim, problems)
            if target is None:
                continue
            edges += 1
            if LAYERS.index(target) > LAYERS.index(own):
                problems.append(f"{path.relative_to(root)} ({own}) includes {included} ({target}): "
                                "against the layer order")
    for p in problems:
        print(p)
    print(f"mysim layers {' < '.join(LAYERS)}: {len(files)} files, {edges} includes inside mysim, "
          f"{len(problems)} against the order")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

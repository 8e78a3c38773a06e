"""The words the report's pages use, each said once."""
import textwrap

from report_style import Page

TERMS = [
    ("w_max", "the highest natural frequency of the scene's springs and masses (rad/s), found by Lanczos "
              "iteration on the stiffness and mass matrices: the fastest mode an explicit step must follow."),
    ("h w_max", "the step times w_max: scale-free. The linear theory keeps an explicit scheme stable for "
                "h w_max < c, with c = 2 for symplectic Euler and Verlet, 2 sqrt 2 for RK4; an engine's step "
                "rule on a scene is h < c / w_max with that scene's w_max."),
    ("E_ref (energy scale)", "what an energy drift is divided by: the larger of |E(0)| and the peak kinetic "
                             "energy of the run (a cloth released at rest at height 0 has E(0) = 0)."),
    ("energy drift", "max |E(t) - E(0)| / E_ref. A conservation check only where nothing drives or damps the "
                     "scene; on a damped one it is the damping, on a driven one the work put in."),
    ("matched scene", "a scene every engine can represent as written (scenes/matched): the same particles, "
                      "springs, forces, pins and colliders in mysim, Bullet and an external engine."),
    ("seed", "the integer that fixes the gusting wind's random field (every engine reads the same table) and "
             "the stability searches' seeded start (free particles moved by up to 1e-4 of the shortest rest "
             "length), so runs repeat bit for bit."),
    ("settled", "every engine's kinetic energy stays below 1e-4 of its peak from some time on, no later than 90 % "
                "into the run: only then is a last frame a rest shape, and final-frame distances a disagreement "
                "of shapes."),
    ("moving, driven", "a cloth not at rest at its last frame (still swinging), or one wind or moving pins "
                       "keep in motion: compared by trajectory over every frame, not by the last frame."),
    ("mirror-aware", "the direct node distance, or the distance to the other engine's mirror image across the "
                     "scene's plane of symmetry (found from the model) where that is under half of it: a fold "
                     "that buckled the other way is not a disagreement."),
    ("drape, drape_max", "node-by-node distance between two engines' last frames (max over nodes)."),
    ("trajectory RMS", "the RMS node distance at each frame both runs sampled, its maximum over the run."),
    ("closed form", "an exact answer the scene has: the circle, the pendulum's period (elliptic integral), the "
                    "hanging chain at rest. Its error near the motion left at the end of the run is that motion, "
                    "not accuracy (the gate notes it)."),
    ("self-consistency", "an engine against its own run at a 16 times finer step: how it converges, whatever "
                         "it converges to."),
    ("Pareto front", "the runs no other run beats on both wall time and error."),
    ("bracketed, stable-at-max", "a stability search found the largest stable step between a stable and an "
                                 "unstable one; or every step tried, up to its largest, was stable."),
    ("precision floor", "for an engine that declares float32: half an ulp of float at the run's largest "
                        "coordinate, the least distance it can be from a double-precision answer."),
]


def draw(fig, ctx):
    y = 0.88
    for term, meaning in TERMS:
        lines = textwrap.wrap(meaning, 150)
        fig.text(0.06, y, term, fontsize=8.5, weight="bold", va="top")
        fig.text(0.22, y, "\n".join(lines), fontsize=8, va="top")
        y -= 0.0155 * len(lines) + 0.012
    return []


def page():
    return Page("glossary", "What do the report's words mean?",
                "The terms the pages use, each once; docs/compare.md and docs/sweeps.md have the measurements "
                "behind them.", draw)

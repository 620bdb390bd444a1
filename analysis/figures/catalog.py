"""Which paper figure each reproduced experiment draws, and what the paper claims there.

One row per figure: the paper (seed file), its figure number, the claim in one line, the run
folder it is drawn from (the experiment file's stem under results/runs/reproduce), the figure
module (analysis/figures/<module>.py), and which of the run's checks belong to it (substrings of
their names; None = all of the run's checks not claimed by an earlier row). A run this table does
not name still appears in the report (under "Other runs") with its checks and every PNG its
kind's plotter drew, so a new kind needs no edit here to be reported; a row only adds the paper's
words and figure number.
"""
import os
from collections import namedtuple

Paper = namedtuple("Paper", "key title seed")
Figure = namedtuple("Figure", "paper figure claim run module checks command", defaults=[None])
# command: how to remake the run when it is not an experiment run (the fit); None = from index.h5.

# How make reproduce draws the render figures (reproduce.toml's [[render]] entry).
_RENDER = ("build/creaturelab run experiments/jellyfish/render_swim.toml --out RUN --force && "
           "build/creaturelab render RUN --frames 36::3 --figures --force")

PAPERS = [
    Paper("mehla", "Mehla 2005, Physically based orb webs (MSc thesis)", "orb-webs-mehla-2005.txt"),
    Paper("rm", "Rudolf & Mould 2009, An interactive fluid model of jellyfish for animation",
          "jellyfish-rudolf-mould-2009.txt"),
    Paper("fluid", "Fluid solver (Rudolf & Mould 2009 §3.2, after Stam 1999)", "jellyfish-rudolf-mould-2009.txt"),
    Paper("fits", "Fits (Rudolf & Mould 2009 §3.3: the Hermite contraction curve)", "jellyfish-rudolf-mould-2009.txt"),
]

FIGURES = [
    # --- Mehla 2005 (seeds/orb-webs-mehla-2005.txt)
    Figure("mehla", "Figs. 5.1-5.2",
           "A strand laid at rest length sags, laid 75-250% over rest it stays taut, Provot's limit caps the "
           "stretch; strands settle in seconds (§5.1).",
           "strand_layouts", "mehla_fig5_2", None),
    Figure("mehla", "Figs. 5.7-5.14",
           "The default web (5,000-7,000 particles, ch. 3) is built frame, spokes, hub, spiral and settles in "
           "5-10 s (§5.1).",
           "default", "mehla_fig5_14", None),
    Figure("mehla", "Fig. 5.17", "Webs of varying sizes: smaller frames hold fewer radii and less spiral.",
           "sizes", "mehla_fig5_17", None),
    Figure("mehla", "Fig. 5.18", "Webs of varying shapes (the frame's attachment points) all settle.",
           "shapes", "mehla_fig5_18", None),
    Figure("mehla", "Figs. 5.19-5.23",
           "Reducing a strand type's spring constant elongates those strands (outer frame, inner frame, radials).",
           "spring_constants", "mehla_fig5_23", None),
    Figure("mehla", "Figs. 5.24-5.28", "Spreading the spoke masses thins the spiral and its coverage.",
           "spiral_spacing", "mehla_fig5_28", None),
    Figure("mehla", "Figs. 5.29-5.33", "Spreading the frame masses gives fewer radial spokes.",
           "spoke_spacing", "mehla_fig5_33", None),
    Figure("mehla", "Figs. 5.34-5.38", "Fewer spokes together with a less dense spiral.",
           "combined", "mehla_fig5_38", None),
    Figure("mehla", "Figs. 5.39-5.44",
           "Backgrounds, alpha blending and shading by strand type (§5.3.7-5.3.8) change how the web reads.",
           "default", "mehla_fig5_44", []),
    Figure("mehla", "Figs. 5.45-5.47", "windgen makes the web billow (§5.3.9).", "wind", "mehla_fig5_46", None),
    Figure("mehla", "Figs. 6.10-6.18",
           "Removing spiral segments that score above 8 inscribes PIG (6.11), with cross-hatch (6.12), random "
           "attachments (6.13) or strong outlines (6.14), an image (6.16) or random gaps (6.18); the web still "
           "settles.",
           "charlotte", "mehla_fig6_11", None),
    # --- Rudolf & Mould 2009 (seeds/jellyfish-rudolf-mould-2009.txt)
    Figure("rm", "Fig. 4",
           "The spring network of a bell slice and its staggered contraction curves; staggered expansion travels "
           "about 68% farther per stroke than unison, and unison still swims (§3.3).",
           "stagger", "rm_fig4", None),
    Figure("rm", "Fig. 4, QUICK",
           "Fig. 4 on the 2026-11-29 default setting, QUICK: 2 mm cells at twice the step. Against 1 mm (stagger, make "
           "reproduce-full) its distance per cycle is 4.9% (staggered) and 9.8% (unison) lower and its "
           "staggered / unison ratio 0.886 against 0.840; both below the paper's 1.68.",
           "stagger_quick", "rm_fig4", None),
    Figure("rm", "Fig. 4 (setting of 2026-12-03)",
           "Fig. 4 on the kind's default setting of 2026-12-03 at its speed peak (0.65 Hz), in the 0.25 m by 0.3 m box (the default "
           "box until the evening of 2026-12-03, pinned): staggered / unison distance per cycle "
           "0.848 on 1 mm at 0.00125 s, 0.846 at its default 0.000625 s, 0.836 on 0.5 mm, 0.834 there with upwind2_rk2 "
           "(the grid, step and "
           "scheme checks pass), not the paper's 1.68; unison swims forward (stagger_default, make reproduce-full).",
           "stagger_default", "rm_fig4", None),
    Figure("rm", "Fig. 4 (default setting since 2026-12-05)",
           "Fig. 4 on the kind's default setting (the force at the step's middle, 1 mm at 0.00125 s, the 0.25 m by "
           "0.36 m box) at 0.65 Hz: staggered / unison distance per cycle 0.844, 0.837 at half the step, 0.839 on "
           "0.5 mm, 0.836 there with upwind2_rk2 (the grid, step and scheme checks pass), not the paper's 1.68; "
           "unison swims forward (stagger_theta, make reproduce-full).",
           "stagger_theta", "rm_fig4", None),
    Figure("rm", "Fig. 5",
           "Distance travelled against contraction frequency has a large maximum at 0.7 Hz, the resonant gait "
           "(§3.3).",
           "frequency_sweep", "rm_fig5", None),
    Figure("rm", "Fig. 5 (converged setting)",
           "The same claim on the pulse-driven bell at nu = 5e-5 m^2/s, 1 mm cells, where the grid agrees to 1% and "
           "the scheme to 5% at 0.6-0.7 Hz (5.7% at 0.8 Hz) and the step is 1-9% from its limit (convergence, "
           "convergence_box_step_viscous; make reproduce-full).",
           "frequency_sweep_viscous", "rm_fig5", None),
    Figure("rm", "Fig. 5 (default setting)",
           "The same claim on the kind's default setting since 2026-12-05: 1 mm cells at 0.00125 s, the elastic force "
           "taken at the step's middle (implicit_theta 0.5), whose grid (0.5 mm: +2.5, +1.3, -3.0% at 0.6-0.8 Hz), "
           "step (+0.5 to +1.4%), scheme (upwind2_rk2: -0.4 to -0.7%) and box (0.6%) checks pass "
           "(convergence_theta). Every mean speed within 0.22% of the earlier setting's: the peak at 0.65 Hz (1.130 "
           "f_n; 1.5% above 0.7 Hz, 4.0% on 0.5 mm), the stroke's at 0.55 Hz (0.956 f_n).",
           "frequency_sweep_theta", "rm_fig5", None),
    Figure("rm", "Fig. 5 (setting of 2026-12-03)",
           "The same claim on the kind's default setting of 2026-12-03 to 12-05: 1 mm cells, the force added after the "
           "advection at 0.000625 s, in a 0.25 m by 0.36 m box 0.2-0.5% below a 0.4 m by 0.6 m one, whose grid "
           "(0.5 mm: +2.4, +1.3, -3.1% at 0.6-0.8 Hz), step (+0.5 to +1.2%), scheme (upwind2_rk2: -0.4 to -0.6%) "
           "and box (1%) checks pass (convergence_default). The mean speed peaks at 0.65 Hz (1.13 f_n; 1.5% above "
           "0.7 Hz, 4.0% on 0.5 mm) and the stroke at 0.55 Hz (0.955 f_n), as on the earlier converged setting "
           "(make reproduce-full).",
           "frequency_sweep_default", "rm_fig5", None),
    Figure("rm", "Fig. 5 (converged setting), QUICK",
           "Fig. 5 on that setting, QUICK: 2 mm cells at twice the step. Against 1 mm at 0.000625 s "
           "(frequency_peak_viscous, make reproduce-full) its distance per cycle is +13.6% at 0.5 Hz, +1.0% at "
           "0.55, -5.0% to -9.8% at 0.6-0.8 Hz, its stroke 2.3-6.7% lower, its f_n 0.09% higher, and both place "
           "the peaks at the same frequencies (mean speed 0.65 Hz, stroke 0.55 Hz).",
           "frequency_sweep_viscous_quick", "rm_fig5", None),
    Figure("rm", "Fig. 5 peaks against f_n (converged setting)",
           "The distance in a given time peaks within 20% of the bell's natural frequency and the stroke "
           "amplitude within 10% (Hoover & Miller 2015; issue 13 §3), 0.05 Hz apart on 1 mm, 1 mm at twice the "
           "step, 2 mm at twice the step and 1 mm with upwind2_rk2: the mean speed peaks at 0.65 Hz (1.13 f_n) and "
           "the stroke at 0.55 Hz (0.955 f_n) in both schemes; at twice the step on 1 mm the mean speed's flat "
           "top tips to 0.7 Hz (1.215 f_n, 0.4% above 0.65 Hz).",
           "frequency_peak_viscous", "rm_fig5", None),
    Figure("rm", "§3.3 (size)",
           "The resonant frequency depends on the diameter of the umbrella: at 2, 4 and 8 cm the distance in a "
           "given time peaks within 20% of each size's natural frequency (issue 13 §3; Hoover & Miller 2015), on "
           "the 2026-11-29 default setting and at twice the cell and step (make reproduce-full).",
           "size_scaling", "rm_size_scaling", None),
    Figure("rm", "Fig. 6", "Trace particles show the fluid flow around the jellyfish through a contraction cycle.",
           "morphology", "rm_fig6", []),
    Figure("rm", "Fig. 11",
           "The morphology of a 4 cm bell through a cycle at 0.7 Hz; it contracts to about 56% of its diameter "
           "(Fig. 3).",
           "morphology", "rm_fig11", None),
    # The 3-D render model (§3.4-3.5), drawn by POV-Ray from a recorded swim (`creaturelab render`).
    Figure("rm", "Fig. 7",
           "Each pair of opposing points of the 2-D slice is revolved into a disc about its own axis; the discs "
           "make the 3-D umbrella (§3.5).",
           "render_swim", "fig07", [], _RENDER),
    Figure("rm", "Fig. 9",
           "Naive extrapolation expanded and contracted, then structural variation, compression ridges and noise "
           "(Eq. 2), and all combined (§3.5).",
           "render_swim", "fig09", [], _RENDER),
    Figure("rm", "Fig. 10",
           "One contraction-expansion cycle of the rendered jellyfish (§3.5).",
           "render_swim", "fig10", None, _RENDER),
    # --- the fluid solver and the fits
    Figure("fluid", "§3.2 (Taylor-Green)",
           "The solver converges to the analytic decaying Taylor-Green vortex as the grid is refined.",
           "taylor_green", "fluid_taylor_green", None),
    Figure("fits", "§3.3 (spline fit)",
           "A Hermite curve with four knots over one period fits the staggered bell's diameter ratio at 0.65 Hz "
           "(the cycles after the warm-up of stagger_quick's staggered point; make reproduce-full fits stagger's).",
           "fit_spline", "fit_spline", None,
           "rm -rf RUN && build/creaturelab fit spline results/runs/reproduce/stagger_quick --point 0 --knots 4 "
           "--from 1.5384615384615385 --out RUN"),
]


def figures_of_run(run_name):
    return [f for f in FIGURES if f.run == run_name]


def has_module(module):
    """Whether analysis/figures/<module>.py exists. A row without one is drawn by its command alone
    (the 3-D renders: `creaturelab render --figures`, reproduce.toml's [[render]] entry)."""
    return os.path.exists(os.path.join(os.path.dirname(os.path.abspath(__file__)), module + ".py"))


def module_of_run(run_name):
    """The figure modules that draw a run folder named run_name: every row's module, except those of
    rows drawn by their command (no module file, a command). A row with neither keeps its name, so
    that draw_runs.py reports the missing module instead of skipping it."""
    return [f.module for f in figures_of_run(run_name) if has_module(f.module) or f.command is None]

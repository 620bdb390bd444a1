"""Which paper figure each reproduced experiment draws, and what the paper claims there.

One row per figure: the paper (by full reference), its figure number, the paper's claim in one line,
the run it is drawn from (the claim file's stem: a run folder of that name under
results/runs/reproduce, or one whose experiment is the stem's QUICK version, <stem>_quick.toml), the
figure module (analysis/figures/<module>.py; None: the kind's plotter draws the run's figures), and
which of the run's checks belong to it (substrings of their names; None = all of the run's checks
not claimed by an earlier row). A run this table does
not name still appears in the report (under "Other runs") with its checks and every PNG its
kind's plotter drew, so a new kind needs no edit here to be reported; a row only adds the paper's
words and figure number.
"""
import os
from collections import namedtuple

Paper = namedtuple("Paper", "key title reference")
Figure = namedtuple("Figure", "paper figure claim run module checks command", defaults=[None])
# command: how to remake the run when it is not an experiment run (the fit); None = from index.h5.

# How make reproduce draws the render figures (reproduce.toml's [[render]] entry).
_RENDER = ("build/creaturelab run experiments/jellyfish/render_swim.toml --out RUN --force && "
           "build/creaturelab render RUN --frames 36::3 --figures --force")

MEHLA = ("A. Mehla, Modeling and Animation of Orb Webs, MSc thesis, University of Saskatchewan, 2005")
RUDOLF_MOULD = ("D. Rudolf and D. Mould, An Interactive Fluid Model of Jellyfish for Animation, VISIGRAPP 2009, "
                "CCIS 68, pp. 59-72, Springer 2010")
LENTINE = ("M. Lentine, J. T. Gretarsson, C. Schroeder, A. Robinson-Mosher and R. Fedkiw, Creature Control in a "
           "Fluid Environment, IEEE Transactions on Visualization and Computer Graphics 16(4), 2010")
TU = "X. Tu, Artificial Animals for Computer Animation: Biomechanics, Locomotion, Perception, and Behavior, " \
     "PhD thesis, University of Toronto, 1996"

PAPERS = [
    Paper("mehla", "Mehla 2005, Modeling and Animation of Orb Webs", MEHLA),
    Paper("rm", "Rudolf & Mould 2009, An Interactive Fluid Model of Jellyfish for Animation", RUDOLF_MOULD),
    Paper("lentine", "Lentine et al. 2010, Creature Control in a Fluid Environment", LENTINE),
    Paper("tu", "Tu 1996, Artificial Animals for Computer Animation", TU),
]

FIGURES = [
    # --- Mehla 2005
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
    # --- Rudolf & Mould 2009
    Figure("rm", "Fig. 4",
           "The spring network of a bell slice and its staggered contraction curves; staggered expansion travels "
           "1.68 times as far per cycle as unison, and unison still swims (§3.3).",
           "stagger", "rm_fig4", None),
    Figure("rm", "Fig. 5 (the default model)",
           "Distance travelled against contraction frequency has a large maximum at 0.7 Hz, the resonant gait "
           "(§3.3). Drawn on the kind's default model: its muscles pull with a tension pulse that the elastic bell "
           "re-expands against, so the stroke comes from the bell, the water and the frequency and can resonate.",
           "frequency", "rm_fig5", None),
    Figure("rm", "Fig. 5 (the paper's model)",
           "The same claim on the paper's own model: muscle springs whose rest length follows §3.3's Hermite curve, "
           "with Fig. 12's joint stiffness. It is not the default because the curve prescribes the stroke at every "
           "frequency, so the bell cannot resonate.",
           "paper_model", "rm_fig5", None),
    Figure("rm", "Fig. 6", "Trace particles show the fluid flow around the jellyfish through a contraction cycle.",
           "morphology", "rm_fig6", []),
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
    Figure("rm", "Fig. 11 (the default model)",
           "The morphology of a 4 cm bell through a cycle at 0.7 Hz; it contracts to about 56% of its diameter "
           "(Fig. 3). Drawn on the kind's default model (tension-pulse muscles, whose stroke can resonate).",
           "morphology", "rm_fig11", None),
    Figure("rm", "Fig. 11 (the paper's model)",
           "The same cycle on the paper's own model (rest-length Hermite muscles, Fig. 12's joint stiffness), "
           "whose curve prescribes the stroke; not the default, which can resonate.",
           "paper_model_morphology", "rm_fig11", None),
    # The fluid solver, the coupling and the fit of §3.2-3.3.
    Figure("rm", "§3.2 (Taylor-Green)",
           "The solver converges to the analytic decaying Taylor-Green vortex as the grid is refined.",
           "taylor_green", "fluid_taylor_green", None),
    Figure("rm", "§3.2 (immersed boundary)",
           "Peskin's immersed boundary method couples the spring-mass body to the grid fluid with a minimal "
           "amount of leakage across the boundary: an elastic membrane keeps its area as it relaxes (§3.2).",
           "membrane", None, None),
    Figure("rm", "§3.3 (spline fit)",
           "A Hermite curve with four knots over one period fits the staggered bell's diameter ratio at 0.65 Hz "
           "(the cycles after the warm-up of stagger's staggered point).",
           "fit_spline", "fit_spline", None,
           "rm -rf RUN && build/creaturelab fit spline results/runs/reproduce/stagger --point 0 --knots 4 "
           "--from 1.5384615384615385 --out RUN"),
    # --- Lentine et al. 2010 (module None: the kind's plotter draws the run's figures)
    Figure("lentine", "Fig. 2",
           "Creature strength sets how quickly the optimum is reached: the first frame at which a converged "
           "solution is reached comes sooner for a stronger creature (§2).",
           "block_wind", None, ["converged frame"]),
    Figure("lentine", "Fig. 6",
           "A block on one controlled joint in a wind minimising drag turns to minimise its exposed area (a), "
           "maximising drag turns broadside to the flow (b) (§3.1, Eq. 2).",
           "block_wind", None, ["aligns the block", "turns the block across", "thick block"]),
    Figure("lentine", "Fig. 4",
           "Minimising effort, the block reaches the global minimum-effort pose: at steady state the net external "
           "force of gravity and wind lies along the block, so the joint's compression carries it; a weaker wind "
           "leans it less (§2.3).",
           "block_effort", None, None),
    Figure("lentine", "Figs. 4, 6 (3-D)",
           "The same optima on a ball joint in 3-D: least and most drag by the exposed area (Fig. 6), the net "
           "force along the block at least effort (Fig. 4) (§2.3, §3.1).",
           "block_ball", None, None),
    Figure("lentine", "Fig. 5",
           "A human with kinematic legs under gravity and wind minimising the back's effort leans into the wind "
           "(a, b); with the arms minimising drag it leans into the wind while holding its arms back (c) (§7).",
           "human_wind", None, None),
    Figure("lentine", "Fig. 7",
           "A swimmer with five controlled legs and a mouth that pumps water swims upward; the propulsion alone "
           "is not enough to move it significantly (§7.2).",
           "swimmer", None, None),
    Figure("lentine", "Fig. 8",
           "In a Navier-Stokes flow the block minimising drag turns near the flow and maximising drag across it, "
           "not exactly horizontal or vertical: a stagnant pocket of fluid lowers the drag (§4.3).",
           "block_flow", None, None),
    Figure("lentine", "Fig. 9",
           "With kinematic legs and gravity, minimising the lower back's effort puts the upper body's centre of "
           "mass straight above the back joint (a); arms minimising their own effort hang down (b) (§7).",
           "human_gravity", None, None),
    Figure("lentine", "Fig. 10 (simple forces)",
           "Each degree of freedom's derivative is computed independently, so n controlled joints on n processors "
           "cost about as much wall time per frame as one (§5; the table below).",
           "parallel_dofs", None, None),
    Figure("lentine", "Fig. 10 (Navier-Stokes)",
           "The same with the full Navier-Stokes fluid, as the paper's Fig. 10 was measured: 14-58 s per frame "
           "serial, 14-15 s on four processors, for 1-4 joints (§5; the table below).",
           "parallel_dofs_fluid", None, None),
    Figure("lentine", "Figs. 11-13",
           "The driven flyer's outer wing joints maximise drag on the down-stroke and minimise it on the "
           "up-stroke, and the flyer's animation closely matches that of many flying creatures (§7.1).",
           "flyer", None, None),
    Figure("lentine", "§3.3, §4.3 (the flyer's derivative)",
           "The steady-state calculation perturbs the pose, sets the velocities to zero and lets the flow respond "
           "to the new configuration, so that the disturbances are swept downstream before the force is read "
           "(§3.3, §4.3): the derivative then has the sign of the force's change between held poses.",
           "flyer_gradient", "lentine_gradient", None),
    Figure("lentine", "§3.3, §4.3 (the 3-D flyer's derivative)",
           "The same steady-state calculation for the 3-D flyer with bending outer joints (§3.3, §4.3, §7.1): "
           "the derivative against the force's change between held poses.",
           "flyer3d_gradient", "lentine_gradient", None),
    Figure("lentine", "Figs. 11-13 (3-D, without flesh)",
           "The same in the paper's own setting, a 3-D fluid: the controlled outer wing joints (bending, Fig. 13) "
           "against held ones, the fluid's mean upward force on the flyer over whole flaps (§7.1).",
           "flyer3d", None, None),
    Figure("lentine", "Fig. 13 (3-D render)",
           "The driven flyer with bending outer joints sheds vortices as it flaps (§7.1, Fig. 13): the Q-criterion "
           "isosurface of the flow with the creature over its last flap.",
           "flyer3d", "lentine_q3d", []),
    Figure("lentine", "Fig. 11 (3-D render)",
           "The driven flyer with twisting outer joints (§7.1, Fig. 11): the Q-criterion isosurface of the flow "
           "with the creature over its last flap.",
           "flyer3d_twist", "lentine_q3d", []),
    Figure("lentine", "§4.1 (3-D fluid)",
           "The paper's 3-D creatures move in an incompressible fluid (§4.1, Eqs. 5-8); our 3-D solver of them "
           "converges at second order to the decaying Taylor-Green vortex (Stokes limit), as the 2-D one is checked.",
           "taylor_green3d", "fluid3d_taylor_green", None),
    Figure("lentine", "§7.1 (the flyer's fluid)",
           "The fluid boundary is open at the top and closed elsewhere, with a source term at the floor forcing "
           "fluid flow upwards (§7.1): here an inflow floor, without the flyer; mass is conserved.",
           "updraft", "fluid3d_updraft", None),
    # --- Tu 1996 (chapters: the thesis's figures are not numbered in the text we cite)
    Figure("tu", "ch. 4 (in air)",
           "The fish's muscles are internal forces in equal and opposite pairs: without the water's reaction the "
           "fish cannot move its centre of mass, and the full-amplitude fish fails in air (ch. 4).",
           "air", None, None),
    Figure("tu", "ch. 4 (stability)",
           "The semi-implicit Euler step of the spring-mass fish is stable at 100-150 times the explicit-Euler "
           "step (ch. 4).",
           "stability", None, None),
    Figure("tu", "ch. 5 (swim)",
           "The swim motor controller's speed grows roughly in proportion to its amplitude and its rate, and "
           "the fish swims straight (ch. 5).",
           "swim", "tu_swim", None),
    Figure("tu", "ch. 5 (swim-MC)",
           "The swim motor controller turns a desired speed into contraction amplitudes and rates (ch. 5).",
           "swim_mc", None, None),
    Figure("tu", "ch. 5 (swim rate)",
           "Speed grows with the swim motor controller's rate over its whole range up to r_max (ch. 5).",
           "swim_rate", None, None),
    Figure("tu", "ch. 5 (turn)",
           "The turn motor controllers turn the swimming fish, more for a stronger and a quicker contraction "
           "(ch. 5): heading over time and the top view of a swim-turn-swim sequence.",
           "turn", "tu_turn", None),
    Figure("tu", "§5 (school)",
           "Several artificial fish are animated together, each an independent biomechanical model (§5).",
           "school", None, None),
    Figure("tu", "ch. 7 (NURBS skin)",
           "The NURBS display surfaces, bound to the dynamic model's faces by patch-nodes and local frames, "
           "deform with the swimming fish, and texture distortions are very small (ch. 7).",
           "skin", "tu_skin", None),
]


def figures_of_run(run_name):
    return [f for f in FIGURES if f.run == run_name]


def has_module(module):
    """Whether analysis/figures/<module>.py exists (never for module None). A row without one is drawn by its command alone
    (the 3-D renders: `creaturelab render --figures`, reproduce.toml's [[render]] entry)."""
    return module is not None and os.path.exists(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                module + ".py"))


def module_of_run(run_name):
    """The figure modules that draw a run folder named run_name: every row's module, except those of
    rows drawn by their command (no module file, a command) and rows whose run's kind plotter draws
    everything (module None). A row with a module name but no file keeps it, so that draw_runs.py
    reports the missing module instead of skipping it."""
    return [f.module for f in figures_of_run(run_name)
            if f.module is not None and (has_module(f.module) or f.command is None)]

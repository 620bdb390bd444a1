# tests for cli/cli: end-to-end runs of the creaturelab executable (label "cli"). Each script is
# self-contained: it cds to the source folder, cleans its scratch folder under the build tree and
# takes well under a minute on 2 cores.
function(creaturelab_cli_test name)
  add_test(NAME cli_${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/${name}.sh $<TARGET_FILE:creaturelab> ${PROJECT_SOURCE_DIR}
                   ${CMAKE_BINARY_DIR}/cli/${name})
  set_tests_properties(cli_${name} PROPERTIES LABELS cli TIMEOUT 300 ${ARGN})
endfunction()

creaturelab_cli_test(bad_input)      # exit 2, one "error:" line, nothing written
creaturelab_cli_test(determinism)    # --jobs 1 == --jobs 2, bitwise (creaturelab digest)
creaturelab_cli_test(resume_kill)    # kill -9 mid-sweep, --resume, equal to an uninterrupted run
creaturelab_cli_test(divergence)     # a diverging point: exit 3, recorded as failed
creaturelab_cli_test(check_compare)  # check, baseline, compare (exit 1 and OUTSIDE on a 1% change)
creaturelab_cli_test(h5py)           # /usr/bin/python3 + h5py reads index, columns, strings, links
creaturelab_cli_test(study_claim)    # a refinement study's unrefined cases are its claim's points, key by key
creaturelab_cli_test(show_list)      # --dry-run writes nothing; show; list
creaturelab_cli_test(fluid_fields)   # /fields shape and chunks, XDMF sidecar, --jobs determinism
creaturelab_cli_test(control)        # block_effort checks, figures, --jobs/threads determinism, bad MJCF and controller input
creaturelab_cli_test(control_fluid)  # small block_flow: --jobs/threads determinism, figures, bad input exit 2, unstable step exit 3
creaturelab_cli_test(flyer)          # small flyer: senses follow the stroke, PD wings flap, --jobs determinism, figures, exit 2 and 3
creaturelab_cli_test(swimmer)  # small swimmer: rise series and figures, unstabilised free creature exit 3, bad phases exit 2
creaturelab_cli_test(jellyfish)      # metrics, series, tracks, fields; --jobs determinism; KNOWN; bad input
creaturelab_cli_test(fish)           # metrics, tracks, skin artifacts (glb parses); --jobs determinism; exit 3 in air; bad input
creaturelab_cli_test(run_folder)     # --points shares, --force, --resume with another configuration
creaturelab_cli_test(folder_lock)    # one writer per folder (fcntl lock, holder's pid); configurations never mix
creaturelab_cli_test(interrupt)      # SIGINT/SIGTERM: 130/143, no *.tmp, a consistent index; stale *.tmp removed
creaturelab_cli_test(render)         # recorded swim -> render.h5/.xdmf, .glb, OBJ, Figs. 7, 9, 10; bad input exits 2
creaturelab_cli_test(report)         # reproduce --list/--out, draw_runs, report.html: every image a PNG, every check shown
creaturelab_cli_test(verify)         # check/compare name truncated, garbage, swapped, foreign point files; --no-verify
# Disk full on a 300 KiB tmpfs: exit 3 and a message, never a signal. Skipped (77) without mount rights.
creaturelab_cli_test(disk_full SKIP_RETURN_CODE 77)
# MPI: skipped (exit 77) without mpirun or an MPI build. RESOURCE_LOCK: 3 ranks on 2 cores.
creaturelab_cli_test(mpi SKIP_RETURN_CODE 77 RESOURCE_LOCK mpi)
# User errors under MPI end every rank once (no rank left waiting in a barrier).
creaturelab_cli_test(mpi_errors SKIP_RETURN_CODE 77 RESOURCE_LOCK mpi)
creaturelab_cli_test(base_file)      # base = "<path>": missing base and cycle exit 2 with the chain; check without the base
creaturelab_cli_test(damaged_index)  # a damaged index.h5 (bad JSON, wrong types, columns of different lengths): exit 2
creaturelab_cli_test(damaged_points) # a corrupt global heap in a point file: check/digest exit 2, --resume recomputes
creaturelab_cli_test(resume_damaged) # --resume recomputes a changed or unreadable point file instead of sealing it
creaturelab_cli_test(limits)         # sweeps over a million points, --points beyond an int, multi-line overrides: exit 2
creaturelab_cli_test(containment)    # names cannot leave --out; links never written through; --force keeps others' files
creaturelab_cli_test(fit_output)     # fit spline: NaN and non-positive options exit 2; an existing output needs --force
# baseline -o on a full 200 KiB tmpfs: exit 2, the old baseline whole. Skipped (77) without mount rights.
creaturelab_cli_test(baseline_disk_full SKIP_RETURN_CODE 77)
# Random damage to a small run's files (200 seeds): every tool exits 0-3 within 10 s, never a signal.
creaturelab_cli_test(fuzz)
creaturelab_cli_test(web_checks_fail) # each web claim check FAILs with its mechanism broken (Provot, wind, drag, spacing)
creaturelab_cli_test(control_checks_fail) # each no-fluid controller claim check FAILs with its mechanism broken (wind, gravity, controller, ranges, contacts; Fig. 10 threads by a one-ulp nudge)
creaturelab_cli_test(reproduce_progress) # reproduce: a line per experiment with the ETA, check tables last; index.h5 provenance, out of the digests
# XDMF readers (meshio, ParaView's pvbatch) open the field sidecar and the render series with the
# HDF5's counts and values. Skipped (77) when neither reader is installed.
creaturelab_cli_test(xdmf_readers SKIP_RETURN_CODE 77)
creaturelab_cli_test(fish_checks_fail) # each fish claim check FAILs with its mechanism broken (water, side current, stiff body, thin skin)
creaturelab_cli_test(control_fluid_checks_fail) # block_flow's and the swimmer's claim checks FAIL with the controller off, the flyer's is inconclusive, Fig. 10's thread checks FAIL on a one-ulp nudge
# Fig. 4's unison check FAILs with the bell's muscles off; 12 s CPU
creaturelab_cli_test(jellyfish_checks_fail TIMEOUT 600)
creaturelab_cli_test(jellyfish_frequency_checks_fail TIMEOUT 600) # Fig. 5's and the bell alone's driven checks FAIL with the muscles off; 22 s CPU
# the membrane's checks FAIL with its mechanism broken (kernels of one width, slack springs, sparse markers); 18 s CPU
creaturelab_cli_test(jellyfish_membrane_checks_fail TIMEOUT 600)
# Fig. 5's file: the bell alone's one-mode check FAILs with tentacles on in its pluck; 18 s CPU
creaturelab_cli_test(jellyfish_bell_checks_fail TIMEOUT 600)
# Fig. 5's speed-peak, stroke-peak and within-20%-of-the-bell's-f_n checks FAIL with the resonance broken (a softer
# bell, a viscous fluid); 20 s CPU
creaturelab_cli_test(jellyfish_resonance_checks_fail TIMEOUT 600 COST 1000)
# the paper model's Fig. 5 and Fig. 11 checks FAIL with its muscles held at rest length or its bell as soft as the default's; 15 s CPU
creaturelab_cli_test(jellyfish_paper_checks_fail TIMEOUT 600)
# the paper model's "unison still swims" (Fig. 4) FAILs with its muscles held at rest length; 19 s CPU
creaturelab_cli_test(jellyfish_paper_stagger_checks_fail TIMEOUT 600)
# the Reynolds study's checks (the bell alone's speed falls with Re, collapses below Re ~ 10) FAIL with the muscles off; 22 s CPU
creaturelab_cli_test(jellyfish_reynolds_checks_fail TIMEOUT 600)
# the fluid3d kind on 8^3: --jobs and threads determinism, the plane of fields and its XDMF, exit 2 and 3; 2.4 s CPU
creaturelab_cli_test(fluid3d)
# the 3-D Taylor-Green claim's convergence checks FAIL with backward Euler in place of Crank-Nicolson or no viscosity; 7.4 s CPU
creaturelab_cli_test(fluid3d_checks_fail)
# the fluid3d kind's whole box (stored_fields = "volume"): (frames, nz, ny, nx) datasets and their XDMF opened by pvbatch; 3.4 s CPU
creaturelab_cli_test(fluid3d_volume SKIP_RETURN_CODE 77)
# the 3-D driven flyer (control_fluid3d) on 16 x 8 x 16 over twelve frames: series, the §7.1 check inconclusive with the controller off, exit 2; 10.9 s CPU
creaturelab_cli_test(flyer3d)
# the 3-D driven flyer wrapped in flesh (control_fluid3d, flesh = true) on 16 x 8 x 16 over twelve frames: series, the §7.1 check inconclusive with the controller off (the breaking test), exit 2; 6.2 s CPU
creaturelab_cli_test(flyer3d_flesh)
# the 3-D driven flyer's renders from its HDF5 (Lentine et al. 2010 Figs. 11, 13): stored_fields = volume on 16 x 8 x 16 over twelve frames, the poses against the hinges' kinematics, lentine_q3d's Q-criterion strips in the house style, creature-glb's .glb, exit 2; 14 s CPU
creaturelab_cli_test(flyer3d_render)
# the 3-D swimmer (control_fluid3d_swimmer) with its legs held in both cases over two cycles: the claim that it rises with the controller FAILs (the breaking test), series and metrics written, bad phases and a body outside the box exit 2; 4.4 s CPU
creaturelab_cli_test(swimmer3d)

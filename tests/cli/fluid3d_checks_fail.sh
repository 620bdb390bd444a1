#!/usr/bin/env bash
# The 3-D Taylor-Green claim's checks (experiments/fluid3d/taylor_green3d.toml, on its quick study's 16^3, 32^3
# and 64^3 over a quarter of the span, 0.5 s) fail when their mechanism is broken: backward Euler in place of
# Crank-Nicolson adds a first-order time error (relative decay-rate error nu k^2 dt 3/2, 0.015 on 16^3), so
# neither order is two and the 64^3 decay rate is not the discrete Laplacian's; without viscosity there is
# no decay to measure (the decay-rate error is not a number). The updraft's mass balance fails with its projection
# cut to one iteration.
# usage: fluid3d_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

quick=studies/fluid3d/taylor_green3d_quick.toml
broken first_order_time "$quick" "decay rate: observed order two" \
  params.end_time_s=0.5 params.viscosity_scheme=backward_euler
also first_order_time "velocity: observed order two"
also first_order_time "64^3: decay-rate error that of the discrete Laplacian, 0.00080 within 5%"

broken no_viscosity "$quick" "decay rate: observed order two" params.end_time_s=0.5 params.kinematic_viscosity_m2_per_s=0
also no_viscosity "64^3: decay-rate error that of the discrete Laplacian, 0.00080 within 5%"

# The updraft (experiments/fluid3d/updraft.toml, over a quarter of its span): one MG-PCG iteration a step
# leaves the projection unconverged, so the flux out of the top no longer equals the floor's.
broken one_pressure_iteration experiments/fluid3d/updraft.toml \
  "mass conserved: the flux out of the open top equals the floor's to 1e-8" \
  params.end_time_s=0.5 params.pressure_max_iterations=1
also one_pressure_iteration "projection: max |div u| dx / max|u| <= 1e-9"

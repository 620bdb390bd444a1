#!/usr/bin/env bash
# Every check that decides a no-fluid controller claim (Lentine et al. 2010, Figs. 2-6 and 9) fails when
# the mechanism the claim rests on is broken: the claim file is run with the wind off (air of zero
# density), gravity off, the controller off (zero strength), the joint ranges or the contacts removed,
# through overrides or a study on it, and the check must then be FAIL in the table with exit code 1.
# Runs are shortened (fewer frames, strengths, speeds, cases) only where the check still resolves.
# usage: control_checks_fail.sh CREATURELAB SOURCE_DIR SCRATCH_DIR
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"  # strict mode, bin src scratch, an empty scratch, fail()
source "$(dirname "${BASH_SOURCE[0]}")/checks_fail_lib.sh"  # status, broken, also, study

# Figs. 2, 3, 6: with no air the drag is zero everywhere, the block stays where it starts (30 degrees off
# the flow) whatever it minimises, and every strength "converges" at once.
broken block_no_wind experiments/control/block_wind.toml \
  "minimising steady drag aligns the block with the flow (within 2 degrees, Fig. 6a)" \
  params.density_kg_per_m3=0.0 'sweep.strength_rad_per_s=[0.5, 1.0]'
also block_no_wind "maximising steady drag turns the block across the flow (within 2 degrees, Fig. 6b)"
also block_no_wind "minimising: the converged frame falls as the strength grows (Fig. 2)"
also block_no_wind "maximising: the converged frame falls as the strength grows (Fig. 2)"
# Eq. 2's thickness term: the thin block in the thick block's place stops on the flow, not atan(t/L) off it
# (the other cases, which the file's checks name, one frame long).
study thin_for_thick experiments/control/block_wind.toml <<'TOML'
[[case]]
label = "min_drag"
frames = 1
average_frames = 1
[[case]]
label = "max_drag"
frames = 1
average_frames = 1
[[case]]
label = "min_drag_thick"
model_file = "experiments/control/models/block.xml"
objectives = "drag"
senses = "min"
steady_state = true
TOML
broken thin_for_thick "$scratch/thin_for_thick.toml" \
  "a thick block (t/L = 0.1) stops where Eq. 2's drag is least, atan(t/L) = 5.7 degrees off the flow" \
  'sweep.strength_rad_per_s=[1.0]'

# Fig. 4: without gravity the wind alone turns the block flat along the flow (90 degrees, not 38);
# without the wind it hangs in both cases: the leans' ratio is 1, not Eq. 2's 0.36.
broken effort_no_gravity experiments/control/block_effort.toml \
  "a 10 m/s wind leans the block 38 degrees from the vertical (Eq. 2 balance, within 1 degree)" \
  params.gravity_m_per_s2=0.0
also effort_no_gravity "a 5 m/s wind leans the block 13.9 degrees from the vertical (Eq. 2 balance, within 1 degree)"
# Without the wind the block hangs where it starts, on its optimum: every strength converges at frame 1.
broken effort_no_wind experiments/control/block_effort.toml \
  "weaker wind, smaller lean (Fig. 4 b against a): Eq. 2's 13.9 / 38.4 = 0.36, each lean within one 0.95-degree step" \
  params.density_kg_per_m3=0.0
also effort_no_wind "the converged frame falls as the strength grows"
# Minimising drag instead of the effort (Eq. 1), the block turns edge-on to the wind, horizontal: off the
# net force's line and fully loaded at every strength, so what effort remains is that load (1.00 of holding
# the block horizontal at 0.5 and at 2 rad/s), not a chatter that grows with the step.
broken effort_min_drag experiments/control/block_effort.toml \
  "1 rad/s: the block's axis lies along the net external force at steady state (within 1 degree, §2.3)" \
  params.objectives=drag
also effort_min_drag "0.5 rad/s: the block's axis lies along the net external force at steady state (within 1 degree, §2.3)"
also effort_min_drag "at 2 rad/s (a 1.9-degree step) the mean pose is within one step of the net force's line"
also effort_min_drag "the sustained effort is near zero: mean torque below 2% of holding the block horizontal"
also effort_min_drag "what effort remains is the chatter of the strength-limited step: 4 times the strength, 4 times the effort"

# Figs. 4 and 6 in 3-D: no air, no drag to minimise or maximise; (c) without the controller the block
# stays horizontal, across the net force and loaded.
broken ball_no_wind experiments/control/block_ball.toml \
  "(a) minimising steady drag reaches Eq. 2's least drag over all orientations, 2 rho u^2 / sqrt(sum A^-2) = 3.394 N" \
  params.density_kg_per_m3=0.0
also ball_no_wind "(b) maximising steady drag turns the broad face across the flow: 2 rho u^2 A = 240 N (within 2%)"
also ball_no_wind "(a) ... edge-on with the diagonal into the flow: the block's line 45.0 degrees off the flow (within 2)"
also ball_no_wind "(b) ... with the block's line across the flow (within 2 degrees)"
study ball_no_control experiments/control/block_ball.toml <<'TOML'
[[case]]
label = "a_min_drag"
frames = 1
average_frames = 1
[[case]]
label = "b_max_drag"
frames = 1
average_frames = 1
[[case]]
label = "c_min_effort"
gravity_m_per_s2 = 9.81
steady_state = true
initial_deg = "ball=0 0 0"
strength_rad_per_s = 0.0
TOML
broken ball_no_control "$scratch/ball_no_control.toml" "(c) the block's line lies along the net external force in 3-D (within 2 degrees)"
also ball_no_control "(c) the sustained effort is near zero: median torque below 5% of holding the block horizontal"

# Fig. 9: without the controller the body stays bent 25 degrees forward, its centre of mass off the
# back and the back loaded; without arm-leg contacts the arms never meet the legs.
broken human_no_control experiments/control/human_gravity.toml \
  "(a) the upper body's centre of mass ends above the lower back: offset below 2 cm (of 18 cm)" \
  params.strength_rad_per_s=0.0 params.search_every_frames=100000 params.frames=150
also human_no_control "(a) the back's effort is near its minimum: median torque below 5% of the upper body held horizontal"
also human_no_control "(b) the back's effort stays near its minimum: median torque below 5% of the upper body held horizontal"
also human_no_control "(b) the right arm comes down: less than 0.8 of its raise in (a)"
also human_no_control "(b) the left arm comes down from its 30-degree raise to rest by the thigh (within 10 degrees of hanging)"
also human_no_control "(c) with legs and forearms swinging the upper body's centre of mass still ends above the lower back (below 2 cm)"
also human_no_control "(c) ... and the back's effort stays near its minimum (median torque below 5%)"
# Fig. 9 (c): with no PD gains the forearms hang instead of swinging (the run's largest miss is over 60
# frames, a prefix of the claim's 300).
broken human_no_pd experiments/control/human_gravity.toml \
  "(c) the PD-driven elbows follow their swing loosely (within 0.05 rad; kp 200 N m/rad)" \
  params.pd_kp_n_m_per_rad=0.0 params.pd_kd_n_m_s_per_rad=0.0 params.frames=60
# With the forearms loose the servo misses its goals by 5.8e-4 rad before the projection (its Newton step is
# exact only without contacts): the check resolves a servo that does not reach them.
also human_no_pd "(c) ... reached by the servo's torques under gravity and contact (miss before the projection below 1e-5 rad)"
# Fig. 9 (c): the kinematic legs land on their patterns exactly because the servo projects its last
# residual away (§2.2, the post-stabilisation of Weinstein et al. 2008); without the projection (a test-only
# switch) they end where the Newton iteration left them, up to 2.8e-11 rad off over 60 frames.
broken human_no_projection experiments/control/human_gravity.toml \
  "(c) walking legs: the kinematic hips and knees are on their sine patterns at every frame's end" \
  params.servo_projection=false params.frames=60
sed 's/conaffinity="2"/conaffinity="0"/' experiments/control/models/humanoid_upper.xml >"$scratch/no_contacts.xml"
broken human_no_contacts experiments/control/human_gravity.toml "the arms meet the legs: contacts are on and used" \
  "params.model_file=\"$scratch/no_contacts.xml\"" params.frames=60

# Fig. 5: with no air nothing pushes the body: it does not lean into the wind and its lean cannot grow
# with the wind speed (case (a) at two speeds; the other cases, which the file's checks name, one frame).
study human_wind_a experiments/control/human_wind.toml <<'TOML'
[params]
frames = 100
[[case]]
label = "a_all_min_back"
objectives = "effort, effort, effort"
senses = "min, min, min"
weights = "1,0,0; 1,0,0; 1,0,0"
[[case]]
label = "b_arms_average"
objectives = "effort, effort, effort"
senses = "min, min, min"
frames = 1
average_frames = 1
[[case]]
label = "c_arms_min_drag"
objectives = "effort, effort, effort"
senses = "min, min, min"
frames = 1
average_frames = 1
[[case]]
label = "d_ball_arms_min_drag"
objectives = "effort, effort, effort"
senses = "min, min, min"
frames = 1
average_frames = 1
TOML
broken human_no_wind "$scratch/human_wind_a.toml" "(a) the body leans into the wind (upstream, more than 5 degrees)" \
  params.density_kg_per_m3=0.0 'sweep.wind_x_m_per_s=[10.0, 30.0]'
also human_no_wind "(a) the lean into the wind grows with the wind, 5-30 m/s"
# Without the joint ranges the back follows the zero-effort lean of a 30 m/s wind past its 25-degree
# extension.
sed 's/limited="true"/limited="false"/' experiments/control/models/humanoid_upper.xml >"$scratch/no_ranges.xml"
broken human_no_ranges "$scratch/human_wind_a.toml" \
  "(a) the back bends back no further than its 25-degree extension (anatomy) and never forward, 5-30 m/s" \
  "params.model_file=\"$scratch/no_ranges.xml\"" 'sweep.wind_x_m_per_s=[10.0, 30.0]'
also human_no_ranges \
  "(a) the body stays upright: centre of mass upwind and within 45 degrees of the vertical (a fold is past 50 downwind), 5-30 m/s"
# Without the shoulders' ranges (the back's kept) the arms balance a 30 m/s wind's load on the back at
# its extension by swinging back past their 60-degree extension (from 30 degrees back, the back at -20).
sed -E 's/(name="(right|left)_shoulder") limited="true"/\1 limited="false"/' experiments/control/models/humanoid_upper.xml \
  >"$scratch/no_shoulder_ranges.xml"
broken human_no_shoulder_ranges "$scratch/human_wind_a.toml" \
  "(a) the arms stay within the shoulder's range (180 degrees of flexion, 60 of extension: anatomy), 5-30 m/s" \
  "params.model_file=\"$scratch/no_shoulder_ranges.xml\"" 'sweep.wind_x_m_per_s=[10.0, 30.0]' \
  'params.initial_deg="lower_back=-20, right_shoulder=30, left_shoulder=30"'
# Fig. 5 (a) without the controller: the upright body with its arms raised holds the wind and its arms with
# the back (median torque 0.42 of the upper body held horizontal at 10 m/s), 27 degrees off the load's line.
broken human_wind_no_control "$scratch/human_wind_a.toml" \
  "(a) the back's effort is near zero: median torque below 5% of the upper body held horizontal" \
  params.strength_rad_per_s=0.0 params.search_every_frames=100000 'sweep.wind_x_m_per_s=[10.0, 30.0]'
also human_wind_no_control \
  "(a) the lean follows the combined force of gravity and wind (within 10 degrees: centre of pressure against mass)"

# Fig. 5 (b), (c): with no air (b) does not lean, and there is no drag for (c)'s arms to minimise: they stay
# where they start (60 and 30 degrees forward) instead of trailing along the flow (at 10 m/s).
study human_wind_bc experiments/control/human_wind.toml <<'TOML'
[params]
frames = 100
[[case]]
label = "a_all_min_back"
objectives = "effort, effort, effort"
senses = "min, min, min"
frames = 1
average_frames = 1
[[case]]
label = "b_arms_average"
objectives = "effort, effort, effort"
senses = "min, min, min"
weights = "1,0,0; 0.5,0.5,0; 0.5,0,0.5"
[[case]]
label = "c_arms_min_drag"
objectives = "effort, drag, drag"
senses = "min, min, min"
[[case]]
label = "d_ball_arms_min_drag"
objectives = "effort, effort, effort"
senses = "min, min, min"
frames = 1
average_frames = 1
TOML
broken human_bc_no_wind "$scratch/human_wind_bc.toml" \
  "(c) the right arm is held back along the flow (hand downstream, past its 60-degree start by more than one 0.95-degree step)" \
  params.density_kg_per_m3=0.0 'sweep.wind_x_m_per_s=[10.0]'
also human_bc_no_wind "(c) the left arm is held back along the flow (from its 30-degree start)"
also human_bc_no_wind "(b) the body leans into the wind"

# Fig. 10 (§5): each joint's central difference is independent, so threads give the serial run bitwise; the
# threads have no switch that breaks that, so a parallel point is moved by one unit in the last place (the
# least a race could change it) and the checks, evaluated again, must fail. The intact run passes first.
intact parallel experiments/control/parallel_dofs.toml params.frames=60
nudged parallel_4_angle "$scratch/run_parallel" "4 joints: two threads give exactly the serial run (final angle)" \
  final_angle_deg 4_joints
nudged parallel_4_effort "$scratch/run_parallel" "4 joints: two threads give exactly the serial run (final effort)" \
  final_effort_n_m_s 4_joints
nudged parallel_2_angle "$scratch/run_parallel" "2 joints: two threads give exactly the serial run (final angle)" \
  final_angle_deg 2_joints

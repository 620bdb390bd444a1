#pragma once
// The central differences of Lentine et al. 2010 §2.1 (Fig. 3) over the controlled DOFs, each
// DOF's two evaluations independent and run in parallel (§5, Fig. 10): shared by the controller
// with simple wind (controller.hpp) and the one in the fluid (fluid_controller.hpp).
#include <functional>
#include <vector>

#include "fluid/worker_pool.hpp"

namespace creaturelab::control {

// evaluate(part, joint, offset_rad): joint's objective after moving it by offset, in the caller's
// scratch copy `part`, one per thread (fluid::thread_piece_count). Each evaluation writes only its
// own slot, so the values do not depend on which thread runs them: bitwise the same for any
// thread count. Returns dJ_i/dq_i per joint: (J(+d) - J(-d)) / 2d, or (J(+d) - J(0)) / d
// one-sided. An exception in an evaluation is rethrown as std::runtime_error "<context>: <what>".
std::vector<double> centralDifferences(fluid::WorkerPool* pool, int joints, double delta_rad, bool one_sided,
                                       const std::function<double(int, int, double)>& evaluate,
                                       const std::string& context);

}  // namespace creaturelab::control

#pragma once
// The dot-peen patent's block snake (CN102689521, "marking control method mixing vector and
// scalar character features"), character by character in text order, in each character's own
// dot matrix (origin top-left, rows downward = the patent's one-way Y, columns = its two-way X):
//
//  1. From the matrix origin, search row by row (Y one way), alternating the direction along each
//     row (X back and forth), for the first dot not yet struck: a block start point. None: the
//     character is done.
//  2. From the start point, snake through the block: one row at a time down, along each row only
//     over the block's run of dots on that row (not the whole window).
//  3. After each step down, if the head's column is inside the row's run but not at either end,
//     it is an X two-way point.
//  4. At a two-way point, run to one end of the run (the nearer), come back past the two-way point
//     and run to the other end.
//  5. Before each step down, sense the next row over the columns just travelled [X2, X1],
//     starting at X2 where the head stands: the first run met continues this block; the start of
//     the next different run met is pushed onto the stack of next-block start points (one per
//     sensing, as claim 2 has it).
//  6. When the block ends, pop start points (skipping any struck since) and go to 2; when the
//     stack is empty, go back to 1.
//
// The track moves one axis at a time, as the patent's does (every track point is one step in X
// or one step in Y from the last, and the blocks' tracks join end to end into the character's):
// a step down that lands beside the next row's run is a corner where the head stops before
// running along the row, and the way to a block's start point goes along Y, then along X, with a
// stop at the corner (X first instead where that corner would leave the window, as it can for a
// rotated or sheared character; straight where both would). A run along a row, and the way back
// past a two-way point, is one move.
#include "marker/peen/dot_text.hpp"
#include "marker/peen/peen_plan.hpp"

namespace mark {

// Home is the window's top-left corner; turn points stay inside the window.
// `one_axis_at_a_time` false drops the corner stops (both axes move together everywhere): not the
// patent's track, but it shows how much of the gap to the optimised planner the corners make.
PeenPlan plan_block_snake(const DotText& text, const Box& window, bool one_axis_at_a_time = true);

}  // namespace mark

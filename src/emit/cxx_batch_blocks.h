// What the batch kernel (cxx_batch.cpp) takes from the loops around its loop
// (cxx_batch_blocks.cpp): the loop's inputs and parameters, the blocks that call it, and
// the scalar kernel's `settle` for the pairs it leaves.
#pragma once

#include "emit/cxx_parts.h"

#include <string>
#include <vector>

namespace impact::emit::cxx_detail {

// One array of a batch kernel, of one scalar a pair: a component of an input or of an output
// named after no input (`fresh`), its array in the batch data, and whether the batch writes it.
struct lane_input {
    std::string name;
    std::string field;
    bool written = false;
    bool fresh = false;  ///< an output's array, written only
};

/// The arrays of `k`'s batch: its inputs' components, parameter by parameter, then the
/// components of the outputs named after no input, output by output.
std::vector<lane_input> lane_inputs(const engine::kernel& k);
/// The parameters of a batch loop: a pointer per scalar input, and the status array.
std::string loop_parameters(const std::vector<lane_input>& inputs, bool with_status);
/// `<loop>_settle`: the pairs the loop left to the scalar kernel (status `underflow`), each
/// resolved by it.
void print_settle(std::string& out, const engine::kernel& k, const std::string& loop,
                  const std::vector<lane_input>& inputs, form which);
/// `<loop>_ahead`: the loop over blocks of 8 pairs, each array's data asked for ahead.
void print_blocks(std::string& out, const std::string& loop, const std::vector<lane_input>& inputs, bool with_status,
                  bool settles, bool sure);
/// The read-only arrays of a batch: the ones a skewed loop reads ahead.
std::vector<lane_input> read_only(const std::vector<lane_input>& inputs);
/// `<loop>_skewed`: the loop over blocks of 8 pairs for arrays that start at one offset
/// within their pages.
void print_skewed_blocks(std::string& out, const std::string& loop, const std::vector<lane_input>& inputs,
                         bool with_status, bool settles, bool sure);

} // namespace impact::emit::cxx_detail

// The loops around a batch kernel's loop (cxx_batch.cpp): its parameters, a pointer per
// array; the blocks of 8 pairs that ask for their data ahead, or read it skewed for arrays
// that crowd one page offset, each trying the sure block first where the kernel has one;
// and the scalar kernel's `settle` for the pairs the loop leaves to it.
#include "emit/cxx_batch_blocks.h"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <sstream>

namespace impact::emit::cxx_detail {
namespace {

// Text with every line indented 4 spaces more.
std::string indented_by_4(const std::string& text)
{
    std::string out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        out += (line.empty() ? "" : "    ") + line + "\n";
    return out;
}

// A line of a block loop asking for an array's data 64 pairs past block b.
std::string prefetch_ahead(const lane_input& in)
{
    return fmt::format("            IMPACT_PREFETCH({}_ + b + ahead, {});\n", in.name, in.written ? 1 : 0);
}

// The arguments a block loop passes to the loop for the block at b: each array from b.
// A loop that settles (see print_settle) always writes statuses: into the caller's array, or,
// where the caller wants none (status_ null), into a block's own.
std::vector<std::string> block_arguments(const std::vector<lane_input>& inputs, bool with_status, bool settles = false)
{
    std::vector<std::string> from_block;
    for (const lane_input& in : inputs)
        from_block.push_back(fmt::format("{}_ + b", in.name));
    if (with_status)
        from_block.push_back(settles ? "status_ ? status_ + b : own" : "with_status ? status_ + b : status_");
    return from_block;
}

} // namespace

std::vector<lane_input> lane_inputs(const engine::kernel& k)
{
    std::vector<lane_input> inputs;
    for (const engine::kernel_parameter& p : k.parameters)
        for (std::size_t c = 0; c < p.components.size(); ++c)
            inputs.push_back({p.components[c].name,
                              p.is_array ? fmt::format("data.{}[{}]", p.name, c) : "data." + p.name,
                              is_output(k, p.name)});
    for (const engine::kernel_output& o : k.outputs)
        if (!k.find_parameter(o.member))
            for (std::size_t c = 0; c < o.values.size(); ++c)
                inputs.push_back({o.own_array_name(c),
                                  o.is_array ? fmt::format("data.{}[{}]", o.member, c) : "data." + o.member, true,
                                  true});
    return inputs;
}

// The parameters of a batch loop: a pointer per scalar input (`restrict`), and the
// status array.
std::string loop_parameters(const std::vector<lane_input>& inputs, bool with_status)
{
    std::vector<std::string> pointers;
    for (const lane_input& in : inputs)
        pointers.push_back(fmt::format("{}Real* IMPACT_RESTRICT {}_", in.written ? "" : "const ", in.name));
    if (with_status)
        pointers.push_back("impact::status* IMPACT_RESTRICT status_");
    return fmt::format("{}", fmt::join(pointers, ", "));
}

// The pairs a batch loop left to the scalar kernel, found by their status `underflow` (a value
// its underflow test tests may be below the normal range, or 0): each resolved by the scalar
// kernel, as one collision, which decides its status exactly. Called after each block.
void print_settle(std::string& out, const engine::kernel& k, const std::string& loop,
                  const std::vector<lane_input>& inputs, form which)
{
    std::vector<std::string> arguments, writes;
    for (const engine::kernel_parameter& p : k.parameters) {
        std::vector<std::string> components;
        for (const engine::quantity& q : p.components)
            components.push_back(q.name + "_[i]");
        arguments.push_back(p.is_array ? fmt::format("std::array<Real, {}>{{{}}}", components.size(), fmt::join(components, ", "))
                                       : components.front());
    }
    if (which == form::fast)
        arguments.push_back("fast_t{}");  // the scalar kernel's fast form
    for (const engine::kernel_output& o : k.outputs) {
        const engine::kernel_parameter* same = k.find_parameter(o.member);
        for (std::size_t c = 0; c < o.values.size(); ++c)
            writes.push_back(fmt::format("        {}_[i] = out.{}{};\n", same ? same->components[c].name : o.own_array_name(c),
                                         o.member, o.is_array ? fmt::format("[{}]", c) : ""));
    }
    out += fmt::format("\n// The pairs {0} left to the scalar {1} (status {2}: a value it tests for underflow may be\n"
                       "// below the normal range), each resolved by it, which decides exactly.\n"
                       "template <class Real>\ninline void {0}_settle(std::size_t count, {3}) noexcept\n{{\n"
                       "    bool doubtful = false;\n"
                       "    for (std::size_t i = 0; i < count; ++i)\n"
                       "        doubtful |= status_[i] == status::{2};\n"
                       "    if (!doubtful)\n        return;\n"
                       "    for (std::size_t i = 0; i < count; ++i) {{\n"
                       "        if (status_[i] != status::{2})\n            continue;\n"
                       "        const auto out = {1}<Real>({4});\n{5}"
                       "        status_[i] = out.status;\n    }}\n}}\n",
                       loop, k.name, underflow, loop_parameters(inputs, true), fmt::join(arguments, ", "),
                       fmt::join(writes, ""));
}

namespace {

// A block loop's call of the sure block for block b, and of the loop (`whole`) where it leaves
// the block. A sure block that leaves its block is not tried on the next 1, 2, 4 ... 16
// blocks, doubling while it keeps leaving them; the results are the same either way. The 2D
// accurate batch in cache (AVX-512), against the loop before sure blocks: ordinary pairs 0.86
// of its time; a fixed sphere or a velocity of 1e-13 in every block 1.01 (1.17 with the sure
// block tried on each), in one block of 16 0.92. The sure block tried in a loop of its own,
// over the blocks from b while it resolves them (AMD EPYC Zen 5, 3 Dec 2026): the fast 2D
// batch in cache 0.37 of the plain loop against 0.36 (AVX-512) and 0.31 against 0.30 (AVX2),
// the accurate 0.17 against 0.22 and 0.13 against 0.16; not taken.
constexpr const char* sure_state = "    std::size_t untried = 0, back_off = 0;  // blocks the sure block skips, and how many next\n";

std::string sure_or_whole(const std::string& loop, const std::string& arguments, const std::string& whole)
{
    return fmt::format("        if (untried == 0 && {0}_sure<Real>({1})) {{\n"
                       "            back_off = 0;\n"
                       "        }} else {{\n"
                       "            if (untried == 0) {{\n"
                       "                back_off = back_off == 0 ? 1 : back_off < 16 ? 2 * back_off : 16;\n"
                       "                untried = back_off;\n"
                       "            }} else {{\n"
                       "                --untried;\n"
                       "            }}\n"
                       "{2}"
                       "        }}\n",
                       loop, arguments, indented_by_4(whole));
}

// The statuses asked for ahead where the caller wants them: a loop that settles is told so by
// status_ not null, one that does not by its template argument.
std::string status_ahead(bool settles)
{
    return fmt::format("            if {}\n                IMPACT_PREFETCH(status_ + b + ahead, 1);\n",
                       settles ? "(status_)" : "constexpr (with_status)");
}

} // namespace

// The batch loop run over blocks of 8 pairs (a cache line of doubles), each array's
// data asked for 64 pairs ahead: out of cache, the hardware's prefetching alone leaves
// the loop waiting for memory (in 3D, 16 arrays streamed at once, a quarter slower).
void print_blocks(std::string& out, const std::string& loop, const std::vector<lane_input>& inputs, bool with_status,
                  bool settles, bool sure)
{
    std::vector<std::string> ahead;
    for (const lane_input& in : inputs)
        ahead.push_back(prefetch_ahead(in));
    if (with_status)
        ahead.push_back(status_ahead(settles));
    const bool by_status = with_status && !settles;  // a template of whether statuses are wanted
    const std::string call = fmt::format("{}<Real{}>", loop, by_status ? ", with_status" : "");
    const std::string arguments = fmt::format("{}", fmt::join(block_arguments(inputs, with_status, settles), ", "));
    const std::string settle = settles ? fmt::format("        {}_settle<Real>(block, {});\n", loop, arguments) : "";
    const std::string whole = fmt::format("        {}(block, {});\n{}", call, arguments, settle);
    const std::string each = sure ? sure_or_whole(loop, arguments, whole) : whole;
    // Asked for only where the arrays hold more than 1 MiB, more than many cores' L2 cache:
    // in cache, the requests and their addresses cost the fast 2D batch (AVX-512, AMD EPYC
    // Zen 5, 2 Dec 2026) a tenth of its speed.
    const std::string bytes = fmt::format("{} * sizeof(Real){}", inputs.size(), with_status ? " + sizeof(impact::status)" : "");
    out += fmt::format("\n// {0} over blocks of 8 pairs, each array's data asked for 64 pairs ahead where the\n"
                       "// arrays hold more than 1 MiB (`far`): the processor's own prefetching, following so\n"
                       "// many arrays, falls behind.\n"
                       "template <class Real{1}>\ninline void {0}_ahead(std::size_t count, {2}) noexcept\n{{\n"
                       "    constexpr std::size_t block = 8, ahead = 64;\n"
                       "    const bool far = count * ({10}) > (std::size_t(1) << 20);\n{6}{9}    std::size_t b = 0;\n"
                       "    for (; b + block <= count; b += block) {{\n        if (far && b + ahead < count) {{\n{3}        }}\n"
                       "{7}    }}\n    {4}(count - b, {5});\n{8}}}\n",
                       loop, by_status ? ", bool with_status" : "", loop_parameters(inputs, with_status),
                       fmt::join(ahead, ""), call, arguments,
                       settles ? "    impact::status own[block];  // the statuses, where the caller wants none\n" : "",
                       each, settles ? fmt::format("    {}_settle<Real>(count - b, {});\n", loop, arguments) : "",
                       sure ? sure_state : "", bytes);
}

// Whether a batch kernel may get a skewed block loop too, for arrays that crowd one page
// offset: one that streams 16 arrays or more (the 2D collide, with 12 arrays, lost by it:
// docs/design-kernels.md, "How the batch loops were shaped"), and has no sure block (print_batch).
bool skews(const engine::kernel& k)
{
    constexpr std::size_t skewed_from = 16;
    return k.batch && lane_inputs(k).size() + (k.guards.empty() ? 0 : 1) >= skewed_from;
}

// The read-only arrays of a batch: the ones a skewed loop reads ahead.
std::vector<lane_input> read_only(const std::vector<lane_input>& inputs)
{
    std::vector<lane_input> read;
    std::copy_if(inputs.begin(), inputs.end(), std::back_inserter(read), [](const lane_input& in) { return !in.written; });
    return read;
}

// The batch loop over blocks of 8 pairs for arrays that start at one offset within their
// pages. Pair i of every array then falls on the same cache sets; the read-only array k
// is read 2 (k + 1) blocks ahead of its turn instead, into a ring of blocks on the stack,
// so that at any time the arrays are read at offsets 128 bytes apart, as if staggered
// (see `skews`; staggered arrays lose a tenth by it, and keep the plain block loop).
void print_skewed_blocks(std::string& out, const std::string& loop, const std::vector<lane_input>& inputs,
                         bool with_status, bool settles, bool sure)
{
    std::vector<std::string> ahead, starts, from_block = block_arguments(inputs, with_status, settles);
    const std::vector<std::string> at_end = from_block;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (inputs[i].written) {
            ahead.push_back(prefetch_ahead(inputs[i]));
            continue;
        }
        // Asked for as many blocks further ahead as it is read ahead: one line an array, as
        // the plain loop asks (a loop over `from` here ran slower and less steadily).
        ahead.push_back(fmt::format("            if (b + ahead + block * lead({0}) < count)\n"
                                    "                IMPACT_PREFETCH({1}_ + b + ahead + block * lead({0}), 0);\n",
                                    starts.size(), inputs[i].name));
        from_block[i] = fmt::format("stage[{}][r]", starts.size());
        starts.push_back(inputs[i].name + "_");
    }
    if (with_status)
        ahead.push_back(status_ahead(settles));
    std::size_t ring = 1;
    while (ring <= 2 * starts.size())  // more blocks than the farthest lead
        ring *= 2;
    const bool by_status = with_status && !settles;  // a template of whether statuses are wanted
    const std::string call = fmt::format("{}<Real{}>", loop, by_status ? ", with_status" : "");
    const std::string whole =
        fmt::format("        {}(block, {});\n{}", call, fmt::join(from_block, ", "),
                    settles ? fmt::format("        {}_settle<Real>(block, {});\n", loop, fmt::join(at_end, ", ")) : "");
    const std::string each = sure ? sure_or_whole(loop, fmt::format("{}", fmt::join(from_block, ", ")), whole) : whole;
    out += fmt::format(
        "\n// {0} over blocks of 8 pairs for arrays that start at one offset within their pages:\n"
        "// pair i of every array then falls on the same cache sets. The read-only array k is read\n"
        "// 2 (k + 1) blocks ahead of its turn, into a ring of blocks, so that the arrays are read\n"
        "// at offsets 128 bytes apart, as if staggered.\n"
        "template <class Real{1}>\ninline void {0}_skewed(std::size_t count, {2}) noexcept\n{{\n"
        "    constexpr std::size_t block = 8, ahead = 64, ring = {3}, read_only = {4};\n{12}{13}"
        "    const Real* const from[read_only] = {{{5}}};\n"
        "    alignas(64) Real stage[read_only][ring][block];\n"
        "    auto lead = [](std::size_t k) {{ return 2 * (k + 1); }};\n"
        "    auto read = [&](std::size_t k, std::size_t j) {{\n"
        "        for (std::size_t i = 0; i < block; ++i)\n"
        "            stage[k][j % ring][i] = from[k][j * block + i];\n"
        "    }};\n"
        "    const std::size_t blocks = count / block;\n"
        "    for (std::size_t k = 0; k < read_only; ++k)\n"
        "        for (std::size_t j = 0; j < lead(k) && j < blocks; ++j)\n"
        "            read(k, j);\n"
        "    std::size_t b = 0;\n"
        "    for (std::size_t j = 0; j < blocks; ++j, b += block) {{\n"
        "        if (b + ahead < count) {{\n{6}        }}\n"
        "        for (std::size_t k = 0; k < read_only; ++k)\n"
        "            if (j + lead(k) < blocks)\n"
        "                read(k, j + lead(k));\n"
        "        const std::size_t r = j % ring;\n"
        "{10}"
        "    }}\n"
        "    {7}(count - b, {9});\n{11}}}\n",
        loop, by_status ? ", bool with_status" : "", loop_parameters(inputs, with_status), ring, starts.size(),
        fmt::join(starts, ", "), fmt::join(ahead, ""), call, fmt::join(from_block, ", "), fmt::join(at_end, ", "),
        each,
        settles ? fmt::format("    {}_settle<Real>(count - b, {});\n", loop, fmt::join(at_end, ", ")) : "",
        settles ? "    impact::status own[block];  // the statuses, where the caller wants none\n" : "",
        sure ? sure_state : "");
}

} // namespace impact::emit::cxx_detail

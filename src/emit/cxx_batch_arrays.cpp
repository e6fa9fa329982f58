// The arrays of a batch kernel's `<name>_batch_data`, owned: one allocation that holds
// them all, each starting at its own offset within a page (cxx_parts.h).
#include "emit/cxx_parts.h"

#include <fmt/format.h>

#include <iterator>

namespace impact::emit::cxx_detail {

std::vector<std::string> batch_members(const engine::kernel& k)
{
    std::vector<std::string> members;
    for (const engine::kernel_parameter& p : k.parameters)
        members.push_back(p.name);
    for (const engine::kernel_output& o : k.outputs)
        if (!k.find_parameter(o.member))
            members.push_back(o.member);
    return members;
}

// The arrays of `<name>_batch_data`, owned, in a layout that keeps a large batch fast: one
// allocation, array k starting 64 + 256 k bytes (modulo 4 KiB) past a page boundary.
void print_batch_arrays(std::string& out, const engine::kernel& k, const member_shapes& shapes)
{
    // Each parameter's first array among all, as C++ in N: the scalars before it, N arrays
    // for each vector before it, and as many as a member shaped by the dimension has there.
    std::vector<std::string> first;
    std::size_t scalars = 0, arrays = 0;
    std::vector<std::string> shaped;
    auto index = [&] {
        std::vector<std::string> terms;
        if (scalars != 0 || (arrays == 0 && shaped.empty()))
            terms.push_back(std::to_string(scalars));
        if (arrays != 0)
            terms.push_back(arrays == 1 ? "N" : std::to_string(arrays) + " * N");
        terms.insert(terms.end(), shaped.begin(), shaped.end());
        return fmt::format("{}", fmt::join(terms, " + "));
    };
    const std::vector<std::string> members = batch_members(k);
    for (const std::string& member : members) {
        first.push_back(index());
        const member_shape& shape = shapes.at(member);
        if (shape.scalar())
            ++scalars;
        else if (shape.follows_dimension())
            ++arrays;
        else
            shaped.push_back(shape.count());
    }
    const std::string reals = index();
    const bool with_status = !k.guards.empty();

    out += fmt::format(
        "\n/// The arrays of {0}_batch_data, owned: one allocation holds them all, array k starting\n"
        "/// 64 + 256 k bytes (modulo 4 KiB) past a page boundary. Arrays allocated one by one all\n"
        "/// start at one offset within their pages: pair i of every array then falls on the same\n"
        "/// cache sets, and a large batch runs about a fifth slower. Each array holds `count`\n"
        "/// values, not initialised, and starts on a 64-byte boundary. The constructor throws\n"
        "/// std::bad_alloc, or std::bad_array_new_length for a count no allocation can hold.\n"
        "/// Move-only; an object moved from holds no arrays.\n"
        "template <class Real, std::size_t N{2}>\nclass {0}_batch_arrays {{\npublic:\n"
        "    static_assert(std::is_floating_point_v<Real>, \"{0}_batch_arrays holds floating-point values\");\n\n"
        "    explicit {0}_batch_arrays(std::size_t count) : count_(count)\n    {{\n"
        "        // Each array padded to whole pages plus `apart`; the bytes in all must not wrap around.\n"
        "        constexpr std::size_t most = (std::numeric_limits<std::size_t>::max() - first - reals * (page + apart)) / per_pair;\n"
        "        if (count > most)\n"
        "            throw std::bad_array_new_length();\n"
        "        stride_ = (count * sizeof(Real) + page - 1) / page * page + apart;\n"
        "        block_ = static_cast<unsigned char*>(::operator new(first + reals * stride_{1}, std::align_val_t{{page}}));\n"
        "        for (std::size_t a = 0; a < reals; ++a)\n"
        "            std::uninitialized_default_construct_n(at<Real>(a), count);\n",
        k.name, with_status ? " + count * sizeof(impact::status)" : "", dimension(k) == 0 ? " = 0" : "");
    if (with_status)
        out += "        std::uninitialized_default_construct_n(at<impact::status>(reals), count);\n";
    out += fmt::format(
        "    }}\n"
        "    {0}_batch_arrays({0}_batch_arrays&& other) noexcept {{ swap(other); }}\n"
        "    {0}_batch_arrays& operator=({0}_batch_arrays&& other) noexcept\n    {{\n"
        "        {0}_batch_arrays(std::move(other)).swap(*this);\n        return *this;\n    }}\n"
        "    {0}_batch_arrays(const {0}_batch_arrays&) = delete;\n"
        "    {0}_batch_arrays& operator=(const {0}_batch_arrays&) = delete;\n"
        "    ~{0}_batch_arrays()\n    {{\n"
        "        if (block_)\n            ::operator delete(block_, std::align_val_t{{page}});\n    }}\n\n"
        "    std::size_t count() const noexcept {{ return count_; }}\n",
        k.name);
    for (std::size_t i = 0; i < members.size(); ++i) {
        const member_shape& shape = shapes.at(members[i]);
        // A member that is a scalar in one dimension and a vector in another: axis 0 by default.
        const std::string axis = shape.scalar()              ? ""
                                 : shape.follows_dimension() ? "std::size_t axis"
                                                             : "std::size_t axis = 0";
        const std::string where = first[i] + (shape.scalar() ? "" : " + axis");
        out += fmt::format("    Real* {0}({1}) noexcept {{ return at<Real>({2}); }}\n"
                           "    const Real* {0}({1}) const noexcept {{ return at<Real>({2}); }}\n",
                           members[i], axis, where);
    }
    if (with_status)
        out += "    impact::status* status() noexcept { return at<impact::status>(reals); }\n"
               "    const impact::status* status() const noexcept { return at<impact::status>(reals); }\n";
    out += fmt::format("\n    /// The arrays as {0}_batch takes them.\n"
                       "    {0}_batch_data<Real, N> data() noexcept\n    {{\n"
                       "        {0}_batch_data<Real, N> d{{}};\n        d.count = count_;\n",
                       k.name);
    for (const std::string& member : members) {
        const member_shape& shape = shapes.at(member);
        auto assigned = [&](const std::string& components) {
            return components == "0" ? fmt::format("d.{0} = {0}();", member)
                                     : fmt::format("for (std::size_t axis = 0; axis < {1}; ++axis)\n"
                                                   "            d.{0}[axis] = {0}(axis);",
                                                   member, components);
        };
        if (shape.scalar())
            out += "        " + assigned("0") + "\n";
        else if (shape.follows_dimension())
            out += "        " + assigned("N") + "\n";
        else {
            // if constexpr (N == 2) { d.w = w(); } else { for (axis < 3) d.w[axis] = w(axis); }
            std::string chain = "        ";
            for (auto c = shape.components.begin(); c != shape.components.end(); ++c) {
                if (c != shape.components.begin())
                    chain += " else ";
                if (std::next(c) != shape.components.end())
                    chain += fmt::format("if constexpr (N == {}) ", c->first);
                std::string body = assigned(std::to_string(c->second));
                if (const auto line = body.find("\n"); line != std::string::npos)
                    body.insert(line + 1, "    ");
                chain += "{\n            " + body + "\n        }";
            }
            out += chain + "\n";
        }
    }
    if (with_status)
        out += "        d.status = status();\n";
    out += fmt::format(
        "        return d;\n    }}\n\n"
        "private:\n"
        "    static constexpr std::size_t reals = {0};  // the arrays of Real{1}\n"
        "    static constexpr std::size_t page = 4096, apart = 256, first = 64;\n"
        "    static constexpr std::size_t per_pair = reals * sizeof(Real){2};  // bytes\n"
        "    template <class T>\n"
        "    T* at(std::size_t a) const noexcept\n    {{\n"
        "        return block_ ? reinterpret_cast<T*>(block_ + first + a * stride_) : nullptr;\n    }}\n"
        "    void swap({3}_batch_arrays& other) noexcept\n    {{\n"
        "        std::swap(count_, other.count_);\n        std::swap(stride_, other.stride_);\n"
        "        std::swap(block_, other.block_);\n    }}\n\n"
        "    std::size_t count_ = 0;\n"
        "    std::size_t stride_ = 0;  // bytes from one array's start to the next\n"
        "    unsigned char* block_ = nullptr;\n"
        "}};\n",
        reals, with_status ? ", then the statuses" : "", with_status ? " + sizeof(impact::status)" : "", k.name);
}

} // namespace impact::emit::cxx_detail

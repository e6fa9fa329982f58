// The binding sources of the Python module: each kernel described to
// src/python/kernel_binding.hpp, with its loops over arrays, printed from engine::kernel.
#include "emit/python.h"

#include "emit/cxx.h"
#include "emit/cxx_parts.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

namespace impact::emit {

using namespace cxx_detail;

namespace {

// `text` as a C++ string literal.
std::string literal(const std::string& text)
{
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        if (c == '\n') {
            out += "\\n\"\n        \"";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

// The docstring of a kernel: its call, its inputs and what it returns. Math stays as the
// file writes it, between dollar signs.
std::string docstring(const engine::derivation& d, const engine::kernel& k)
{
    std::vector<std::string> names;
    for (const engine::kernel_parameter& p : k.parameters)
        names.push_back(p.name);
    const std::size_t n = dimension(k);
    std::string doc = fmt::format("{}({}, *, fast=False, out=None): {}{}{}.\n", k.name, fmt::join(names, ", "),
                                  d.source.title.value, d.source.paper ? ", " + d.source.paper->value : "",
                                  n ? fmt::format(" ({} components)", n) : "");
    // Each input by how it is passed, then its quantity: "C_M[..., 0] (C_Mx): ...".
    for (const engine::kernel_parameter& p : k.parameters)
        for (std::size_t c = 0; c < p.components.size(); ++c) {
            const engine::quantity& q = p.components[c];
            std::string described = describe(q);
            // Doxygen's \f$ back to the file's $.
            for (std::size_t at; (at = described.find("\\f$")) != std::string::npos;)
                described.replace(at, 3, "$");
            const std::string passed = p.is_array ? fmt::format("{}[..., {}]", p.name, c) : p.name;
            // describe() starts with the quantity's name.
            doc += passed == q.name ? fmt::format("  {}\n", described)
                                    : fmt::format("  {} ({}){}\n", passed, q.name, described.substr(q.name.size()));
        }
    std::vector<std::string> fields;
    for (const engine::kernel_output& o : k.outputs)
        fields.push_back(o.member);
    if (has_status(k))
        fields.push_back("status");
    doc += returns_scalar(k) ? fmt::format("Returns {} (NaN where the inputs are refused); out= an array to write it into.",
                                           k.outputs.front().member)
                             : fmt::format("Returns the fields {}; out= a tuple of arrays to write them into.",
                                           fmt::join(fields, ", "));
    return doc;
}

// The index of the parameter an output is written over (an output named after an input), or -1.
int written_over(const engine::kernel& k, const engine::kernel_output& o)
{
    for (std::size_t p = 0; p < k.parameters.size(); ++p)
        if (k.parameters[p].name == o.member)
            return static_cast<int>(p);
    return -1;
}

// Whether the binding calls the kernel's batch loop: one that returns a structure (a kernel
// returning one scalar returns NaN where refused).
bool calls_batch(const engine::kernel& k)
{
    return k.batch && !returns_scalar(k);
}

// The loop over pairs calling the scalar kernel: input component j at in<j>[i * step<j>]
// (at in<j>[i] where every input has a value a pair, `Strided` false: no multiplication a
// pair), output component j at out<j>[i].
void print_scalar_loop(std::string& out, const engine::kernel& k)
{
    out += fmt::format("template <class Real, bool Strided, class... Form>\n"
                       "inline void loop_{}(const impact::python::columns& c, Form... form) noexcept\n{{\n",
                       k.name);
    std::vector<std::string> arguments;
    std::size_t j = 0;
    for (const engine::kernel_parameter& p : k.parameters) {
        std::vector<std::string> components;
        for (std::size_t i = 0; i < p.components.size(); ++i, ++j) {
            out += fmt::format("    const Real* const in{0} = static_cast<const Real*>(c.in[{0}]);\n"
                               "    const std::size_t step{0} = c.step[{0}];\n",
                               j);
            components.push_back(fmt::format("in{0}[Strided ? i * step{0} : i]", j));
        }
        arguments.push_back(p.is_array ? fmt::format("std::array<Real, {}>{{{}}}", p.components.size(),
                                                     fmt::join(components, ", "))
                                       : components.front());
    }
    std::vector<std::string> stores;
    std::size_t o = 0;
    for (const engine::kernel_output& output : k.outputs) {
        const std::size_t count = output.is_array ? output.values.size() : 1;
        for (std::size_t i = 0; i < count; ++i, ++o) {
            out += fmt::format("    Real* const out{0} = static_cast<Real*>(c.out[{0}]);\n", o);
            if (returns_scalar(k))
                stores.push_back(fmt::format("out{}[i] = r;", o));
            else
                stores.push_back(output.is_array ? fmt::format("out{}[i] = r.{}[{}];", o, output.member, i)
                                                 : fmt::format("out{}[i] = r.{};", o, output.member));
        }
    }
    if (has_status(k)) {
        out += "    impact::status* const status = c.status;\n";
        stores.push_back("status[i] = r.status;");
    }
    out += fmt::format("    for (std::size_t i = 0; i < c.count; ++i) {{\n"
                       "        const auto r = impact::{}<Real>({}, form...);\n"
                       "        {}\n    }}\n}}\n\n",
                       k.name, fmt::join(arguments, ", "), fmt::join(stores, "\n        "));
    // The runner, compiled for the host's FMA and AVX2 too where the compiler can choose at load
    // time (IMPACT_PYTHON_LOOP, kernel_binding.hpp), the kernel inlined into it.
    out += fmt::format("template <class Real>\nIMPACT_PYTHON_LOOP void run_{0}(const impact::python::columns& c, "
                       "bool fast) noexcept\n{{\n"
                       "    if (impact::python::strided(c))\n"
                       "        fast ? loop_{0}<Real, true>(c, impact::fast) : loop_{0}<Real, true>(c);\n"
                       "    else\n"
                       "        fast ? loop_{0}<Real, false>(c, impact::fast) : loop_{0}<Real, false>(c);\n}}\n\n",
                       k.name);
}

// The batch kernel called on the columns, every input an array of `count` values: each input
// written over copied into its output's column (the output named after it) first, here, where
// the GIL is released, unless the caller passed the input's own array as that output (`out=`); the outputs named after no input written into their columns. (Copied and
// run a chunk of pairs at a time, so that the loop would find the copies in cache, 3D collide's
// 4 million pairs took 94 ms in chunks of 65 536, against 75 ms at once: chunks of fewer pairs
// than the block loops ask for ahead of.)
void print_batch_call(std::string& out, const engine::kernel& k)
{
    out += fmt::format("template <class Real, class... Form>\n"
                       "void loop_{0}(const impact::python::columns& c, Form... form) noexcept\n{{\n"
                       "    impact::{0}_batch_data<Real, {1}> d{{}};\n    d.count = c.count;\n",
                       k.name, dimension(k));
    // The output columns of each output, by output order.
    std::map<std::string, std::size_t> first_output_column;
    std::size_t o = 0;
    for (const engine::kernel_output& output : k.outputs) {
        first_output_column[output.member] = o;
        o += output.is_array ? output.values.size() : 1;
    }
    std::size_t j = 0;
    for (const engine::kernel_parameter& p : k.parameters) {
        const auto written = first_output_column.find(p.name);
        for (std::size_t i = 0; i < p.components.size(); ++i, ++j) {
            const std::string member = p.is_array ? fmt::format("d.{}[{}]", p.name, i) : "d." + p.name;
            if (written != first_output_column.end())
                out += fmt::format("    {0} = static_cast<Real*>(c.out[{1}]);\n"
                                   "    impact::python::copy_over(c.in[{2}], {0}, c.count);\n",
                                   member, written->second + i, j);
            else
                out += fmt::format("    {} = static_cast<const Real*>(c.in[{}]);\n", member, j);
        }
    }
    // The outputs named after no input, into their own columns.
    for (const engine::kernel_output& output : k.outputs) {
        if (written_over(k, output) >= 0)
            continue;
        const std::size_t column = first_output_column[output.member];
        for (std::size_t i = 0; i < output.values.size(); ++i)
            out += fmt::format("    d.{}{} = static_cast<Real*>(c.out[{}]);\n", output.member,
                               output.is_array ? fmt::format("[{}]", i) : "", column + i);
    }
    if (!k.guards.empty())
        out += "    d.status = c.status;\n";
    out += fmt::format("    impact::{}_batch(d, form...);\n}}\n\n", k.name);
}

// The description of a kernel registered with the binding, and its runner.
void print_registration(std::string& out, const engine::derivation& d, const engine::kernel& k)
{
    std::vector<std::string> parameters;
    for (const engine::kernel_parameter& p : k.parameters)
        parameters.push_back(fmt::format("{{\"{}\", {}}}", p.name, p.is_array ? p.components.size() : 0));
    std::vector<std::string> outputs;
    for (const engine::kernel_output& o : k.outputs)
        outputs.push_back(fmt::format("{{\"{}\", {}, {}}}", o.member, o.is_array ? o.values.size() : 0,
                                      written_over(k, o)));
    out += fmt::format("    r.add({{\"{}\", {}, {{{}}},\n           {{{}}},\n"
                       "           /*status=*/{}, /*returns_scalar=*/{}, /*batch=*/{},\n"
                       "        {},\n           &run_{}<float>, &run_{}<double>}});\n",
                       k.name, dimension(k), fmt::join(parameters, ", "), fmt::join(outputs, ", "),
                       has_status(k), returns_scalar(k), calls_batch(k), literal(docstring(d, k)), k.name,
                       k.name);
}

// One derivation file's translation unit.
std::string binding_source(const engine::derivation& d)
{
    const std::string binder = python_binder_name(d.source.file);
    std::string out = fmt::format("// Generated by Impact from {}; do not edit.\n", d.source_name());
    if (d.kernels.empty())
        return out + fmt::format("// It has no kernels.\n\nnamespace impact::python {{\n\nclass registry;\n\n"
                                 "void {}(registry&)\n{{\n}}\n\n}} // namespace impact::python\n",
                                 binder);
    out += fmt::format("// Its kernels for NumPy arrays (src/python/kernel_binding.hpp).\n\n"
                       "#include \"impact/{}\"\n#include \"python/kernel_binding.hpp\"\n\n"
                       "#include <algorithm>\n#include <array>\n#include <cstddef>\n\nnamespace impact::python {{\nnamespace {{\n\n"
                       "// The loops under the kernels' own options (common.hpp), so that GCC inlines the kernels\n"
                       "// into them: it inlines no function compiled under other optimisation options.\n"
                       "IMPACT_PRECISE_BEGIN\n\n",
                       kernel_header_name(d));
    for (const engine::kernel& k : d.kernels) {
        if (!calls_batch(k)) {
            print_scalar_loop(out, k);
            continue;
        }
        print_batch_call(out, k);
        // Compiled for x86-64-v3 too, as a scalar loop's runner is (IMPACT_PYTHON_LOOP): without
        // FMA in the baseline, each std::fma of the loop is a call, and the loop no vector loop.
        out += fmt::format("template <class Real>\nIMPACT_PYTHON_LOOP void run_{0}(const impact::python::columns& c, bool fast) noexcept\n"
                           "{{\n    if (fast)\n        loop_{0}<Real>(c, impact::fast);\n    else\n"
                           "        loop_{0}<Real>(c);\n}}\n\n",
                           k.name);
    }
    out += fmt::format("IMPACT_PRECISE_END\n\n}} // namespace\n\nvoid {}(registry& r)\n{{\n", binder);
    for (const engine::kernel& k : d.kernels)
        print_registration(out, d, k);
    out += "}\n\n} // namespace impact::python\n";
    return out;
}

} // namespace

std::string python_binder_name(const std::string& file)
{
    std::string name = "bind_";
    for (char c : std::filesystem::path(file).stem().string()) {
        const bool word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        name += word ? c : '_';
    }
    return name;
}

std::map<std::string, std::string> python_binding_files(const engine::library& lib)
{
    std::map<std::string, std::string> files;
    std::vector<const engine::kernel*> kernels;
    std::vector<std::string> binders;
    std::set<std::string> file_names;
    for (const engine::derivation* d : lib.in_order()) {
        const std::string binder = python_binder_name(d->source.file);
        const std::string name = "python/" + std::filesystem::path(d->source.file).stem().string() + ".cpp";
        if (!file_names.insert(name).second || std::find(binders.begin(), binders.end(), binder) != binders.end())
            throw error({d->source.file, 0, 0},
                        fmt::format("the Python binding of derivation '{}' would be {} ({}), as another file's is; "
                                    "rename the file",
                                    d->id(), name, binder));
        binders.push_back(binder);
        files[name] = binding_source(*d);
        for (const engine::kernel& k : d->kernels)
            kernels.push_back(&k);
    }
    std::string module = fmt::format("// Generated by Impact from {}; do not edit.\n"
                                     "// The module impact._impact: every derivation file's kernels, and the statuses.\n\n"
                                     "#include \"impact/common.hpp\"\n#include \"python/kernel_binding.hpp\"\n\n"
                                     "#include <pybind11/pybind11.h>\n\n"
                                     "namespace impact::python {{\n\n",
                                     engine::source_folder(lib.in_order()));
    for (const std::string& binder : binders)
        module += fmt::format("void {}(registry& r);\n", binder);
    module += "\n} // namespace impact::python\n\nPYBIND11_MODULE(_impact, m)\n{\n    impact::python::registry r;\n";
    for (const std::string& binder : binders)
        module += fmt::format("    impact::python::{}(r);\n", binder);
    std::vector<std::string> statuses;
    for (const std::string& s : status_names(kernels))
        statuses.push_back(fmt::format("{{\"{0}\", impact::status::{0}}}", s));
    module += fmt::format("    r.define(m);\n    impact::python::define_statuses(m, {{{}}});\n}}\n",
                          fmt::join(statuses, ", "));
    files["python/module.cpp"] = module;
    return files;
}

} // namespace impact::emit

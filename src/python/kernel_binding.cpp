// A kernel's call from Python: the arguments by name, their dtype and shapes checked, broadcast
// and laid out as columns, the runner run without the GIL, the outputs returned as arrays.
#include "python/kernel_binding.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Python.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace py = pybind11;

namespace impact::python {
namespace {

using shape = std::vector<py::ssize_t>;

std::string text_of(const shape& s)
{
    std::string text = "(";
    for (std::size_t i = 0; i < s.size(); ++i)
        text += (i ? ", " : "") + std::to_string(s[i]);
    return text + (s.size() == 1 ? ",)" : ")");
}

py::tuple tuple_of(const shape& s)
{
    py::tuple t(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
        t[i] = py::int_(s[i]);
    return t;
}

shape shape_of(const py::array& a)
{
    return shape(a.shape(), a.shape() + a.ndim());
}

// The arguments in the order of the parameters, from the positional and keyword arguments;
// `fast` and `out` from their keywords (no kernel's parameter has either name: the engine
// refuses them as names its C++ declares).
std::vector<py::object> arguments_by_parameter(const kernel_entry& e, const py::args& args, const py::kwargs& kwargs,
                                               bool& fast, py::object& out)
{
    const std::string function = e.name + "()";
    if (args.size() > e.parameters.size())
        throw py::type_error(function + " takes " + std::to_string(e.parameters.size()) +
                             " arguments (and fast=, out=), " + std::to_string(args.size()) + " were given");
    std::vector<py::object> values(e.parameters.size());
    for (std::size_t i = 0; i < args.size(); ++i)
        values[i] = args[i];
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::str(key);
        if (name == "fast") {
            if (!py::isinstance<py::bool_>(value))
                throw py::type_error(function + ": fast must be True or False");
            fast = value.cast<bool>();
            continue;
        }
        if (name == "out") {
            if (!value.is_none())
                out = py::reinterpret_borrow<py::object>(value);
            continue;
        }
        const auto p = std::find_if(e.parameters.begin(), e.parameters.end(),
                                    [&](const parameter& q) { return q.name == name; });
        if (p == e.parameters.end())
            throw py::type_error(function + " got an unexpected keyword argument '" + name + "'");
        py::object& slot = values[static_cast<std::size_t>(p - e.parameters.begin())];
        if (slot)
            throw py::type_error(function + " got multiple values for argument '" + name + "'");
        slot = py::reinterpret_borrow<py::object>(value);
    }
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!values[i])
            throw py::type_error(function + " missing argument '" + e.parameters[i].name + "'");
    return values;
}

// Whether the arguments call for float32: every array among them (NumPy's arrays and
// scalars, of a real dtype) is float32, and one is. A Python float or int follows the arrays.
bool in_float32(const kernel_entry& e, const std::vector<py::object>& values, std::vector<py::array>& arrays)
{
    const py::module_ numpy = py::module_::import("numpy");
    bool any32 = false, other = false;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const py::object& x = values[i];
        const bool python_number = PyFloat_CheckExact(x.ptr()) || PyLong_CheckExact(x.ptr());
        arrays.push_back(numpy.attr("asarray")(x));
        const py::dtype dtype = arrays.back().dtype();
        const char kind = dtype.kind();
        const std::string where = e.name + "(): argument '" + e.parameters[i].name + "'";
        if (kind == 'f' && (dtype.itemsize() == 4 || dtype.itemsize() == 8)) {
            if (!python_number)
                (dtype.itemsize() == 4 ? any32 : other) = true;
        } else if (kind == 'i' || kind == 'u') {
            other = other || !python_number;
        } else {
            throw py::type_error(where + " has dtype " + dtype.attr("name").cast<std::string>() +
                                 "; the kernels take real numbers, float32 or float64 (or integers, as float64)");
        }
    }
    return any32 && !other;
}

// The shape all the pairs broadcast to, from each argument's shape of pairs (a vector's
// without its last axis), by NumPy's rules.
shape broadcast(const kernel_entry& e, const std::vector<shape>& shapes)
{
    shape all;
    std::vector<std::size_t> from;  // the argument each axis of `all` was set by (counted from the end)
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const shape& s = shapes[i];
        if (s.size() > all.size()) {
            all.insert(all.begin(), s.size() - all.size(), 1);
            from.insert(from.begin(), s.size() - from.size(), i);
        }
        for (std::size_t k = 0; k < s.size(); ++k) {
            py::ssize_t& a = all[all.size() - s.size() + k];
            const py::ssize_t b = s[k];
            std::size_t& by = from[all.size() - s.size() + k];
            if (b == a || b == 1)
                continue;
            if (a != 1)
                throw py::value_error(e.name + "(): argument '" + e.parameters[i].name + "' has pairs of shape " +
                                      text_of(s) + ", which does not broadcast with " + text_of(shapes[by]) +
                                      " of argument '" + e.parameters[by].name + "'");
            a = b;
            by = i;
        }
    }
    return all;
}

// The entry among `entries` (one name, several dimensions) for the arguments: the one whose
// dimension is the last axis of the first vector argument.
const kernel_entry& entry_for(const std::vector<kernel_entry>& entries, const std::vector<py::object>& values)
{
    const kernel_entry& first = entries.front();
    const auto vector = std::find_if(first.parameters.begin(), first.parameters.end(),
                                     [](const parameter& p) { return p.components != 0; });
    if (entries.size() == 1 || vector == first.parameters.end())
        return first;
    const std::size_t v = static_cast<std::size_t>(vector - first.parameters.begin());
    const py::array a = py::module_::import("numpy").attr("asarray")(values[v]);
    std::string dimensions;
    for (const kernel_entry& e : entries) {
        if (a.ndim() >= 1 && static_cast<std::size_t>(a.shape(a.ndim() - 1)) == e.dimension)
            return e;
        dimensions += (dimensions.empty() ? "" : " or ") + std::to_string(e.dimension);
    }
    throw py::value_error(first.name + "(): argument '" + vector->name + "' must be a vector of " + dimensions +
                          " components (an array of shape (..., N)); it has shape " + text_of(shape_of(a)));
}

// The fields of a kernel's result, in order: its outputs, then its status where it has one.
std::vector<std::string> field_names(const kernel_entry& e)
{
    std::vector<std::string> names;
    for (const output& o : e.outputs)
        names.push_back(o.name);
    if (e.status)
        names.push_back("status");
    return names;
}

// The arrays the caller gave for the result (`out=`), checked: a tuple (a named tuple of an
// earlier call's result, say) of one array for each field, or an array alone for a kernel that
// returns one value; each of the call's dtype (int64 for the statuses), writeable, of the
// pairs' shape (a vector's components last), each component's values contiguous over the
// pairs, as a fresh output's are (a vector of shape (n, N) in Fortran order).
std::vector<py::array> given_outputs(const kernel_entry& e, const py::object& out, const shape& all, bool float32)
{
    const std::vector<std::string> names = field_names(e);
    const std::size_t wanted = e.returns_scalar ? 1 : names.size();
    std::vector<py::object> objects;
    if (e.returns_scalar && py::isinstance<py::array>(out)) {
        objects.push_back(out);
    } else if (py::isinstance<py::tuple>(out) || py::isinstance<py::list>(out)) {
        for (const py::handle item : out)
            objects.push_back(py::reinterpret_borrow<py::object>(item));
    }
    std::string list;
    for (std::size_t f = 0; f < wanted; ++f)
        list += (f ? ", " : "") + names[f];
    if (objects.size() != wanted) {
        const std::string it = py::isinstance<py::tuple>(out) || py::isinstance<py::list>(out)
                                   ? "it has " + std::to_string(objects.size())
                                   : "it is of type " + py::str(py::type::of(out).attr("__name__")).cast<std::string>();
        throw py::type_error(e.name + "(): out must be " +
                             (e.returns_scalar ? "an array for " + list
                                               : "a tuple of " + std::to_string(wanted) + " arrays, one for each field (" +
                                                     list + ")") +
                             "; " + it);
    }
    std::vector<py::array> arrays;
    for (std::size_t f = 0; f < wanted; ++f) {
        const bool is_status = names[f] == "status";
        const std::size_t components = is_status ? 0 : e.outputs[f].components;
        const std::string where = e.name + "(): out '" + names[f] + "'";
        if (!py::isinstance<py::array>(objects[f]))
            throw py::type_error(where + " must be a NumPy array; it is of type " +
                                 py::str(py::type::of(objects[f]).attr("__name__")).cast<std::string>());
        py::array a = py::reinterpret_borrow<py::array>(objects[f]);
        const py::dtype dtype = a.dtype();
        const bool native = dtype.attr("isnative").cast<bool>();
        const std::string type = is_status ? "int64" : float32 ? "float32" : "float64";
        const bool right = native && (is_status ? dtype.kind() == 'i' && dtype.itemsize() == 8
                                                : dtype.kind() == 'f' && dtype.itemsize() == (float32 ? 4 : 8));
        if (!right)
            throw py::type_error(where + " has dtype " +
                                 (native ? dtype.attr("name").cast<std::string>()
                                         : dtype.attr("str").cast<std::string>() + " (not in the machine's byte order)") +
                                 "; it must be " + type + (is_status ? " (the statuses' type)" : " (the type the call computes in)"));
        shape expected = all;
        if (components != 0)
            expected.push_back(static_cast<py::ssize_t>(components));
        if (shape_of(a) != expected)
            throw py::value_error(where + " has shape " + text_of(shape_of(a)) + "; the call's pairs give " +
                                  text_of(expected));
        if (!a.writeable())
            throw py::value_error(where + " is read-only");
        for (std::size_t k = 0; k < std::max<std::size_t>(components, 1); ++k) {
            const py::array column = components ? a.attr("__getitem__")(py::make_tuple(py::ellipsis(), k)) : a;
            if (!(column.flags() & py::array::c_style) || !column.attr("flags").attr("aligned").cast<bool>())
                throw py::value_error(where + " must hold " +
                                      (components ? "each component's values" : std::string("its values")) +
                                      " contiguous and aligned over the pairs, as np.empty(" +
                                      (components ? "(n, " + std::to_string(components) + "), order='F')" : "n)") +
                                      " does; it does not");
        }
        // A vector's columns, each contiguous, apart: the loop writes each through a pointer of
        // its own (common.hpp: the arrays written overlap no other), so components closer than
        // a column's length, or at one place (a stride of 0), would overwrite each other.
        py::ssize_t pairs = 1;
        for (py::ssize_t n : all)
            pairs *= n;
        if (components > 1 && pairs > 0 && std::abs(a.strides(a.ndim() - 1)) < pairs * dtype.itemsize())
            throw py::value_error(where + " has components that overlap one another (its last axis's stride is " +
                                  std::to_string(a.strides(a.ndim() - 1)) + " bytes, less than a column of " +
                                  std::to_string(pairs) + " values)");
        arrays.push_back(a);
    }
    return arrays;
}

// Whether two arrays are the same values: same memory, shape and strides (a stride of an
// axis of one element moves nothing).
bool same_array(const py::array& a, const py::array& b)
{
    if (a.data() != b.data() || shape_of(a) != shape_of(b))
        return false;
    for (py::ssize_t k = 0; k < a.ndim(); ++k)
        if (a.shape(k) > 1 && a.strides(k) != b.strides(k))
            return false;
    return true;
}

// The caller's outputs share no memory with one another, nor with an argument, except an
// output with the very array of the input it is written over (in place): a batch loop reads
// an input after the outputs of earlier pairs are written, so any other overlap would change
// what it reads.
void refuse_overlap(const kernel_entry& e, const std::vector<py::array>& given, const std::vector<py::array>& arguments)
{
    const py::object may_share = py::module_::import("numpy").attr("may_share_memory");
    const std::vector<std::string> names = field_names(e);
    for (std::size_t f = 0; f < given.size(); ++f) {
        const std::string where = e.name + "(): out '" + names[f] + "'";
        for (std::size_t g = 0; g < f; ++g)
            if (may_share(given[f], given[g]).cast<bool>())
                throw py::value_error(where + " shares memory with out '" + names[g] + "'");
        for (std::size_t i = 0; i < arguments.size(); ++i) {
            if (!may_share(given[f], arguments[i]).cast<bool>())
                continue;
            const bool in_place = f < e.outputs.size() && e.outputs[f].written_over == static_cast<int>(i) &&
                                  same_array(given[f], arguments[i]);
            if (!in_place)
                throw py::value_error(where + " shares memory with argument '" + e.parameters[i].name +
                                      "': an output may share memory only with the input it updates, and only as "
                                      "that very array (in place)");
        }
    }
}

py::object call(const std::vector<kernel_entry>& entries, const py::object& result_type, const py::args& args,
                const py::kwargs& kwargs)
{
    bool fast = false;
    py::object out_given;
    std::vector<py::object> values = arguments_by_parameter(entries.front(), args, kwargs, fast, out_given);
    const kernel_entry& e = entry_for(entries, values);
    std::vector<py::array> arrays;
    const bool float32 = in_float32(e, values, arrays);
    const py::module_ numpy = py::module_::import("numpy");
    const py::object dtype = numpy.attr(float32 ? "float32" : "float64");

    // Each argument's shape of pairs: a vector's without its components.
    std::vector<shape> pairs;
    for (std::size_t i = 0; i < arrays.size(); ++i) {
        const parameter& p = e.parameters[i];
        shape s = shape_of(arrays[i]);
        if (p.components != 0) {
            if (s.empty() || static_cast<std::size_t>(s.back()) != p.components)
                throw py::value_error(e.name + "(): argument '" + p.name + "' must be a vector of " +
                                      std::to_string(p.components) + " components (an array of shape (..., " +
                                      std::to_string(p.components) + ")); it has shape " + text_of(s));
            s.pop_back();
        }
        pairs.push_back(s);
        arrays[i] = numpy.attr("asarray")(arrays[i], dtype);
    }
    const shape all = broadcast(e, pairs);
    py::ssize_t count = 1;
    for (py::ssize_t n : all)
        count *= n;
    const py::tuple all_shape = tuple_of(all);

    // The outputs: the caller's arrays (out=), each component's column where it is, or one
    // fresh row of `count` values per component.
    std::vector<py::array> given;
    if (out_given) {
        given = given_outputs(e, out_given, all, float32);
        refuse_overlap(e, given, arrays);
    }
    std::vector<py::array> rows;
    columns c;
    c.count = static_cast<std::size_t>(count);
    const py::ssize_t item = float32 ? 4 : 8;
    for (std::size_t o = 0; o < e.outputs.size(); ++o) {
        const output& out = e.outputs[o];
        const py::ssize_t components = static_cast<py::ssize_t>(std::max<std::size_t>(out.components, 1));
        if (!given.empty()) {
            for (py::ssize_t k = 0; k < components; ++k)
                c.out.push_back(static_cast<char*>(given[o].mutable_data()) +
                                (out.components ? k * given[o].strides(given[o].ndim() - 1) : 0));
            continue;
        }
        rows.push_back(numpy.attr("empty")(py::make_tuple(components, count), dtype));
        for (py::ssize_t k = 0; k < components; ++k)
            c.out.push_back(static_cast<char*>(rows.back().mutable_data()) + k * count * item);
    }
    py::array statuses;
    if (e.status) {
        statuses = given.size() > e.outputs.size() ? given.back() : py::array(numpy.attr("empty")(count, numpy.attr("int64")));
        c.status = static_cast<impact::status*>(statuses.mutable_data());
    }

    // The inputs' columns: each component as it is where it is contiguous with every pair's
    // value, one value for all where the argument has one pair (a scalar loop only), a copy
    // otherwise. In a batch call an input written over is taken alike, and the runner copies
    // it into its output before the loop (print_batch_call in emit/python.cpp).
    std::vector<py::object> kept;
    for (std::size_t i = 0; i < arrays.size(); ++i) {
        const parameter& p = e.parameters[i];
        for (std::size_t k = 0; k < std::max<std::size_t>(p.components, 1); ++k) {
            py::array view = p.components ? arrays[i].attr("__getitem__")(py::make_tuple(py::ellipsis(), k)) : arrays[i];
            // An array's values need not be aligned to their type (np.frombuffer at an odd
            // offset); the kernels read them as Real, so such a column is copied.
            const bool aligned = view.attr("flags").attr("aligned").cast<bool>();
            if (view.size() == 1 && !e.batch && aligned) {
                c.in.push_back(view.data());
                c.step.push_back(0);
                continue;
            }
            if (shape_of(view) != all)
                view = numpy.attr("broadcast_to")(view, all_shape);
            if (!(view.flags() & py::array::c_style) || !aligned)
                view = numpy.attr("require")(view, py::none(), py::make_tuple("C", "A"));
            kept.push_back(view);
            c.in.push_back(view.data());
            c.step.push_back(1);
        }
    }

    const runner run = float32 ? e.run_float : e.run_double;
    if (c.count != 0) {
        py::gil_scoped_release unlocked;
        run(c, fast);
    }

    // The caller's arrays as they were given; else each output as an array of the pairs'
    // shape, its components last; one pair's as a NumPy scalar (or a vector of its components).
    if (!given.empty()) {
        if (e.returns_scalar)
            return given.front();
        py::tuple values_of_fields(given.size());
        for (std::size_t f = 0; f < given.size(); ++f)
            values_of_fields[f] = given[f];
        return result_type(*values_of_fields);
    }
    std::vector<py::object> fields;
    for (std::size_t o = 0; o < e.outputs.size(); ++o) {
        const output& out = e.outputs[o];
        py::object field;
        if (out.components == 0) {
            field = rows[o].attr("__getitem__")(0).attr("reshape")(all_shape);
            if (all.empty())
                field = field.attr("__getitem__")(py::tuple());
        } else {
            shape vectors = all;
            vectors.insert(vectors.begin(), static_cast<py::ssize_t>(out.components));
            field = numpy.attr("moveaxis")(rows[o].attr("reshape")(tuple_of(vectors)), 0, -1);
        }
        fields.push_back(field);
    }
    if (e.returns_scalar)
        return fields.front();
    if (e.status) {
        py::object field = statuses.attr("reshape")(all_shape);
        fields.push_back(all.empty() ? field.attr("__getitem__")(py::tuple()) : field);
    }
    py::tuple values_of_fields(fields.size());
    for (std::size_t f = 0; f < fields.size(); ++f)
        values_of_fields[f] = fields[f];
    return result_type(*values_of_fields);
}

} // namespace

void registry::add(kernel_entry entry)
{
    for (const kernel_entry& e : entries_) {
        if (e.name != entry.name)
            continue;
        bool same = e.parameters.size() == entry.parameters.size() && e.outputs.size() == entry.outputs.size();
        for (std::size_t i = 0; same && i < e.parameters.size(); ++i)
            same = e.parameters[i].name == entry.parameters[i].name;
        for (std::size_t i = 0; same && i < e.outputs.size(); ++i)
            same = e.outputs[i].name == entry.outputs[i].name;
        if (!same || e.dimension == entry.dimension || e.status != entry.status ||
            e.returns_scalar != entry.returns_scalar)
            throw std::logic_error("the kernels named " + entry.name +
                                   " differ in more than their dimension: one Python function cannot call them");
    }
    entries_.push_back(std::move(entry));
}

void registry::define(py::module_& m) const
{
    // Each docstring starts with the call as Python takes it, not pybind11's (*args, **kwargs).
    py::options options;
    options.disable_function_signatures();
    const py::object namedtuple = py::module_::import("collections").attr("namedtuple");
    py::list names;
    py::dict layouts;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        const std::string& name = entries_[i].name;
        if (std::any_of(entries_.begin(), entries_.begin() + static_cast<long>(i),
                        [&](const kernel_entry& e) { return e.name == name; }))
            continue;
        std::vector<kernel_entry> same;
        std::string doc;
        for (const kernel_entry& e : entries_)
            if (e.name == name) {
                same.push_back(e);
                doc += (doc.empty() ? "" : "\n\n") + e.doc;
            }
        py::list fields;
        for (const output& o : same.front().outputs)
            fields.append(o.name);
        if (same.front().status)
            fields.append("status");
        const py::object result_type = namedtuple(name + "_result", fields);
        result_type.attr("__module__") = "impact";
        m.def(
            name.c_str(),
            [same, result_type](const py::args& args, const py::kwargs& kwargs) {
                return call(same, result_type, args, kwargs);
            },
            doc.c_str());
        names.append(name);
        // Each dimension's parameters and outputs, for impact.batch_arrays (batch.py).
        py::list forms;
        for (const kernel_entry& e : same) {
            py::list parameters, outputs;
            for (const parameter& p : e.parameters)
                parameters.append(py::make_tuple(p.name, p.components));
            for (const output& o : e.outputs)
                outputs.append(py::make_tuple(o.name, o.components, o.written_over));
            forms.append(py::dict(py::arg("dimension") = e.dimension, py::arg("parameters") = parameters,
                                  py::arg("outputs") = outputs, py::arg("status") = e.status,
                                  py::arg("returns_scalar") = e.returns_scalar, py::arg("batch") = e.batch));
        }
        layouts[name.c_str()] = forms;
    }
    m.attr("kernel_names") = names;
    m.attr("kernel_layouts") = layouts;
}

void define_statuses(py::module_& m, const std::vector<std::pair<std::string, impact::status>>& statuses)
{
    py::list names;
    for (const auto& [name, value] : statuses)
        names.append(py::make_tuple(name, static_cast<std::int64_t>(value)));
    m.attr("status_names") = names;
}

} // namespace impact::python

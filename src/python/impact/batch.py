"""Arrays laid out for a kernel's batch loop (docs/python.md, "In place").

``impact.batch_arrays(impact.collide, n, dimension=3)`` makes the arrays of ``n`` pairs that a
call reads and writes without a copy, laid out as C++'s ``collide_batch_arrays`` lays them out
(common.hpp): every component an array of its own in one block, the first 64 bytes past a page
boundary and each next one 256 bytes further on (modulo 4 KiB), so that pair i of the arrays
a loop reads together never falls on one offset within their pages, and every array aligned
for the widest vector loads. A vector is an array of shape (n, N) whose columns are those
arrays. An output written over an input (the velocities) is that input's array, so that

    b = impact.batch_arrays(impact.collide, n, dimension=3)
    b.M[:], b.v_M[:], ... = ...
    impact.collide(*b.inputs, out=b.out)

updates the velocities in place, as ``collide_batch`` does in C++.
"""

import numpy as _np

from . import _impact

_PAGE, _APART, _FIRST = 4096, 256, 64


class BatchArrays:
    """The arrays of one kernel's pairs: one for each parameter, for each output named after
    no input, and ``status`` where the kernel has one, each by its name (``b["v_M"]``, and
    ``b.v_M`` where the name is none of this object's own: ``kernel``, ``count``, ``dtype``,
    ``inputs``, ``out``, ``fields``); ``inputs``, the parameters' arrays in order; ``out``, the
    arrays to pass as ``out=`` (an output named after an input is that input's array)."""

    def __init__(self, name, count, dtype, inputs, out, fields):
        self.kernel = name
        self.count = count
        self.dtype = dtype
        self.inputs = inputs
        self.out = out
        self.fields = dict(fields)

    def __getitem__(self, name):
        return self.fields[name]

    def __getattr__(self, name):
        # Called only for names that are not the object's own.
        fields = self.__dict__.get("fields", {})
        if name in fields:
            return fields[name]
        raise AttributeError(f"impact.BatchArrays of {self.__dict__.get('kernel', '?')} has no array '{name}'")

    def __repr__(self):
        return (f"<impact.BatchArrays of {self.kernel} for {self.count} pairs, {self.dtype.name}: "
                f"{', '.join(self.fields)}>")


def _form(kernel, dimension):
    name = kernel if isinstance(kernel, str) else getattr(kernel, "__name__", None)
    forms = _impact.kernel_layouts.get(name) if isinstance(name, str) else None
    if forms is None:
        raise ValueError(f"impact.batch_arrays(): {kernel!r} is none of the module's kernels "
                         f"({', '.join(_impact.kernel_names)})")
    dimensions = [f["dimension"] for f in forms]
    if dimension is None:
        if len(forms) > 1:
            raise ValueError(f"impact.batch_arrays(): {name} has forms in dimensions "
                             f"{' and '.join(map(str, dimensions))}; give dimension=")
        return name, forms[0]
    for f in forms:
        if f["dimension"] == dimension:
            return name, f
    raise ValueError(f"impact.batch_arrays(): {name} has no form in dimension {dimension} "
                     f"(it has {' and '.join(map(str, dimensions))})")


def batch_arrays(kernel, count, *, dimension=None, dtype=_np.float64):
    """Arrays for ``count`` pairs of ``kernel`` (a kernel of this package, or its name), laid out
    for its batch loop; ``dimension`` picks the form of a kernel with several (collide: 2 or
    3); ``dtype`` float64 or float32. The values are not set (as ``numpy.empty``'s)."""
    name, form = _form(kernel, dimension)
    dtype = _np.dtype(dtype)
    if not dtype.isnative or dtype not in (_np.dtype(_np.float32), _np.dtype(_np.float64)):
        raise TypeError(f"impact.batch_arrays(): dtype must be float32 or float64 in the machine's byte order; "
                        f"it is {dtype.str if not dtype.isnative else dtype.name}")
    if isinstance(count, bool) or not isinstance(count, (int, _np.integer)) or count < 0:
        raise ValueError(f"impact.batch_arrays(): count must be a whole number of pairs, 0 or more; it is {count!r}")
    count = int(count)
    fresh = [(o, c) for o, c, over in form["outputs"] if over < 0]
    columns = sum(max(c, 1) for _, c in form["parameters"]) + sum(max(c, 1) for _, c in fresh)
    stride = -(-count * dtype.itemsize // _PAGE) * _PAGE + _APART
    statuses = count * 8 if form["status"] else 0
    block = _np.empty(_PAGE + _FIRST + columns * stride + statuses, _np.uint8)
    start = -block.ctypes.data % _PAGE + _FIRST
    taken = 0

    def take(components):
        nonlocal taken
        offset = start + taken * stride
        taken += max(components, 1)
        if components == 0:
            return _np.ndarray((count,), dtype, buffer=block, offset=offset)
        return _np.ndarray((count, components), dtype, buffer=block, offset=offset,
                           strides=(dtype.itemsize, stride))

    fields = {}
    for parameter, components in form["parameters"]:
        fields[parameter] = take(components)
    inputs = tuple(fields.values())
    out = []
    for output, components, over in form["outputs"]:
        if over >= 0:
            out.append(inputs[over])
        else:
            fields[output] = take(components)
            out.append(fields[output])
    if form["status"]:
        fields["status"] = _np.ndarray((count,), _np.int64, buffer=block, offset=start + columns * stride)
        if not form["returns_scalar"]:
            out.append(fields["status"])
    return BatchArrays(name, count, dtype, inputs, out[0] if form["returns_scalar"] else tuple(out), fields)

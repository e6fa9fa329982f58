"""Impact's kernels on NumPy arrays (docs/python.md).

Each kernel Impact derives is a function of this module, generated from the kernel as the
engine describes it: ``impact.collide_line(M, m, v_M, v_m, eps)`` takes scalars or arrays
(broadcast as NumPy does; vectors as arrays of shape (..., 2) or (..., 3)) in float32 or
float64, and returns its outputs under the names of the C++ result's fields. ``fast=True``
calls the kernel's fast form, ``out=`` writes the results into arrays the caller gives (the
velocities in place where they are the inputs' own arrays), and ``impact.batch_arrays`` makes
arrays laid out as the batch loops read them. ``impact.status`` names the values of the
``status`` field.
"""

import enum as _enum

from . import _impact
from .batch import BatchArrays, batch_arrays
from .derivation import Derivation, DerivationError, derive

#: Why a kernel refused its inputs (``impact.status.separating``); ``ok`` when it computed
#: its outputs. Compares equal to the values of a result's ``status`` array.
status = _enum.IntEnum("status", _impact.status_names, module=__name__)

for _name in _impact.kernel_names:
    globals()[_name] = getattr(_impact, _name)

#: The kernels' names, in the order the module defines them.
kernel_names = list(_impact.kernel_names)

__all__ = ["status", "derive", "Derivation", "DerivationError", "batch_arrays", "BatchArrays", *_impact.kernel_names]
del _name

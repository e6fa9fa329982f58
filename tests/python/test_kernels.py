"""The kernels from Python (src/python, docs/python.md): results bit for bit the C++ kernels',
physics laws and closed forms, broadcasting, dtypes, layouts, statuses and bad input.

Run by CTest (test_python) with the interpreter the package is built for, PYTHONPATH at the
build's python/ folder, IMPACT_KERNEL_REFERENCE the C++ kernels called pair by pair
(tests/python/kernel_reference.cpp) and IMPACT_KERNELS the generated headers' folder.
"""

import os
import re
import subprocess

import numpy as np
import pytest

import impact

REFERENCE = os.environ.get("IMPACT_KERNEL_REFERENCE")
KERNELS = os.environ.get("IMPACT_KERNELS")


def ulps(dtype):
    return np.finfo(dtype).eps


# ---------------------------------------------------------------------------------------------
# Bit for bit: the module against the C++ kernels, called pair by pair.

def random_line(rng, n, dtype):
    """collide_line's and energy_loss's inputs: masses over six decades, approaching or not."""
    M = 10.0 ** rng.uniform(-3, 3, n)
    m = 10.0 ** rng.uniform(-3, 3, n)
    v_M = rng.normal(0, 5, n)
    v_m = rng.normal(0, 5, n)
    eps = rng.uniform(0, 1, n)
    return [x.astype(dtype) for x in (M, m, v_M, v_m, eps)]


def random_space(rng, n, dtype):
    M = 10.0 ** rng.uniform(-2, 2, n)
    m = 10.0 ** rng.uniform(-2, 2, n)
    C_M = rng.normal(0, 1, (n, 3))
    C_m = rng.normal(0, 1, (n, 3))
    v_M = rng.normal(0, 3, (n, 3))
    v_m = rng.normal(0, 3, (n, 3))
    eps = rng.uniform(0, 1, n)
    return [x.astype(dtype) for x in (M, m, C_M, C_m, v_M, v_m, eps)]


def random_rough_plane(rng, n, dtype):
    M = 10.0 ** rng.uniform(-2, 2, n)
    m = 10.0 ** rng.uniform(-2, 2, n)
    R_M = rng.uniform(0.1, 2, n)
    R_m = rng.uniform(0.1, 2, n)
    q_M = rng.uniform(0.1, 2 / 3, n)
    q_m = rng.uniform(0.1, 2 / 3, n)
    C_M = rng.normal(0, 1, (n, 2))
    C_m = rng.normal(0, 1, (n, 2))
    v_M = rng.normal(0, 3, (n, 2))
    v_m = rng.normal(0, 3, (n, 2))
    w_M = rng.normal(0, 3, n)
    w_m = rng.normal(0, 3, n)
    eps = rng.uniform(0, 1, n)
    beta = rng.uniform(-1, 1, n)
    mu = np.where(rng.uniform(0, 1, n) < 0.2, np.inf, rng.uniform(0, 1, n))
    return [x.astype(dtype) for x in (M, m, R_M, R_m, q_M, q_m, C_M, C_m, v_M, v_m, w_M, w_m, eps, beta, mu)]


def reference(kernel, dtype, fast, inputs, outputs, status, tmp_path):
    """The C++ kernel's outputs, component by component, and its statuses."""
    n = len(inputs[0])
    columns = []
    for x in inputs:
        columns += [x] if x.ndim == 1 else [x[:, k] for k in range(x.shape[1])]
    path_in, path_out = tmp_path / "in", tmp_path / "out"
    np.concatenate(columns).astype(dtype).tofile(path_in)
    subprocess.run([REFERENCE, kernel, "float" if dtype == np.float32 else "double",
                    "fast" if fast else "accurate", str(n), str(path_in), str(path_out)], check=True)
    raw = path_out.read_bytes()
    values = np.frombuffer(raw[: outputs * n * np.dtype(dtype).itemsize], dtype=dtype).reshape(outputs, n)
    statuses = np.frombuffer(raw[outputs * n * np.dtype(dtype).itemsize:], dtype=np.int64) if status else None
    return values, statuses


def components(result_fields):
    """A result's fields as columns, a vector's component by component."""
    columns = []
    for x in result_fields:
        columns += [x] if x.ndim == 1 else [x[:, k] for k in range(x.shape[1])]
    return columns


def same_bits(a, b):
    """Equal bit for bit (NaNs of the same payload and sign too)."""
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    assert a.dtype == b.dtype
    view = np.uint32 if a.dtype == np.float32 else np.uint64
    return np.array_equal(a.view(view), b.view(view))


needs_reference = pytest.mark.skipif(REFERENCE is None, reason="IMPACT_KERNEL_REFERENCE not set (run by CTest)")

CASES = [
    # name in kernel_reference, Python function, inputs, number of output components, status
    ("collide_line", impact.collide_line, random_line, 3, True),      # a batch loop, J in a column of its own
    ("energy_loss", impact.energy_loss, random_line, 1, False),       # a kernel returning a scalar
    ("collide_3d", impact.collide, random_space, 6, True),            # a batch loop
    ("collide_rough_2d", impact.collide_rough, random_rough_plane, 6, True),  # a batch loop, spins scalars
]


@needs_reference
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("fast", [False, True])
@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_results_are_the_cxx_kernels_bit_for_bit(case, fast, dtype, tmp_path):
    name, function, draw, outputs, status = case
    inputs = draw(np.random.default_rng(62), 1000, dtype)
    result = function(*inputs, fast=fast)
    fields = [result] if not status and not isinstance(result, tuple) else list(result)
    expected, expected_status = reference(name, dtype, fast, inputs, outputs, status, tmp_path)
    got = components(fields[:-1] if status else fields)
    assert len(got) == outputs
    for k in range(outputs):
        assert got[k].dtype == dtype
        assert same_bits(got[k], expected[k]), f"{name} output component {k} differs from the C++ kernel"
    if status:
        assert np.array_equal(result.status, expected_status)
        # The draws reach both sides of the guards: pairs resolved and pairs refused.
        assert np.any(result.status == impact.status.ok)
        assert np.any(result.status == impact.status.separating)


# ---------------------------------------------------------------------------------------------
# Physics laws and closed forms, typed here.

def test_equal_masses_elastic_collision_exchanges_velocities():
    r = impact.collide_line(2.0, 2.0, 3.0, -1.5, 1.0)
    assert r.status == impact.status.ok
    assert r.v_M == pytest.approx(-1.5, rel=4 * ulps(np.float64))
    assert r.v_m == pytest.approx(3.0, rel=4 * ulps(np.float64))
    # J = M m / (M + m) (1 + eps) (v_M - v_m) = 1 * 2 * 4.5
    assert r.J == pytest.approx(9.0, rel=4 * ulps(np.float64))


def test_momentum_is_conserved_and_energy_lost_as_eq_11_says():
    M, m, v_M, v_m, eps = random_line(np.random.default_rng(1), 2000, np.float64)
    r = impact.collide_line(M, m, v_M, v_m, eps)
    ok = r.status == impact.status.ok
    assert ok.sum() > 500
    scale = (M + m) * np.maximum(np.abs(v_M), np.abs(v_m))
    momentum = M * r.v_M + m * r.v_m - (M * v_M + m * v_m)
    assert np.all(np.abs(momentum[ok]) <= 64 * ulps(np.float64) * scale[ok])
    # Eq. 11: the kinetic energy changes by -(1 - eps^2)/2 * M m/(M + m) * (v_M - v_m)^2.
    loss = impact.energy_loss(M, m, v_M, v_m, eps)
    closed = -(1 - eps) * (1 + eps) / 2 * M * m / (M + m) * (v_M - v_m) ** 2
    np.testing.assert_allclose(loss[ok], closed[ok], rtol=1e-12, atol=0)
    before = 0.5 * M * v_M**2 + 0.5 * m * v_m**2
    after = 0.5 * M * r.v_M**2 + 0.5 * m * r.v_m**2 - before
    assert np.all(np.abs(after - closed)[ok] <= 1e-13 * before[ok])


def test_a_fixed_sphere_reflects_the_other_with_its_restitution():
    # M = +infinity: v_M unchanged, v_m' = (1 + eps) v_M - eps v_m.
    r = impact.collide_line(np.inf, 1.0, 0.5, -2.0, 0.25)
    assert r.status == impact.status.ok
    assert r.v_M == 0.5
    assert r.v_m == pytest.approx(1.25 * 0.5 + 0.25 * 2.0, rel=4 * ulps(np.float64))


def test_a_head_on_elastic_collision_in_space_exchanges_velocities_along_the_line_of_centres():
    r = impact.collide(1.0, 1.0, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 1.0, 0.0], [0.0, 0.0, -3.0], 1.0)
    np.testing.assert_allclose(r.v_M, [0.0, 1.0, 0.0], atol=4 * ulps(np.float64))
    np.testing.assert_allclose(r.v_m, [2.0, 0.0, -3.0], atol=4 * ulps(np.float64))


# ---------------------------------------------------------------------------------------------
# Statuses: the C++ contract's answers to bad values, with names.

def test_statuses_have_their_cxx_names_and_refused_pairs_keep_their_velocities():
    M = np.array([1.0, -1.0, 1.0, 1.0, np.nan])
    v_M = np.array([1.0, 1.0, -1.0, 1.0, 1.0])
    eps = np.array([0.5, 0.5, 0.5, 2.0, 0.5])
    r = impact.collide_line(M, 1.0, v_M, 0.0, eps)
    assert [impact.status(s).name for s in r.status] == [
        "ok", "invalid_mass", "separating", "invalid_restitution", "invalid_mass"]
    refused = r.status != impact.status.ok
    np.testing.assert_array_equal(r.v_M[refused], v_M[refused])
    np.testing.assert_array_equal(r.v_m[refused], 0.0)


def test_a_kernel_returning_a_scalar_returns_nan_where_it_refuses():
    loss = impact.energy_loss([1.0, -1.0], 1.0, 1.0, 0.0, 0.5)
    assert np.isfinite(loss[0]) and np.isnan(loss[1])


def test_every_kernel_of_the_generated_headers_is_a_function_of_the_module():
    if KERNELS is None:
        pytest.skip("IMPACT_KERNELS not set (run by CTest)")
    names = set()
    for header in os.listdir(KERNELS):
        with open(os.path.join(KERNELS, header)) as f:
            # Each kernel's documentation: "/// name(parameters): title" at the start of a line.
            names |= set(re.findall(r"^/// (\w+)\([^)]*\): ", f.read(), re.M))
    names = {n for n in names if not n.endswith("_batch")}
    assert len(names) >= 5
    assert names == set(impact.kernel_names)
    assert all(callable(getattr(impact, n)) and n in impact.__all__ for n in names)


# ---------------------------------------------------------------------------------------------
# Broadcasting, layouts and dtypes.

def test_arguments_broadcast_as_numpy_broadcasts():
    M = np.array([[1.0], [2.0], [4.0], [8.0]])
    v_M = np.array([1.0, 2.0, 3.0])
    r = impact.collide_line(M, 1.0, v_M, -1.0, 0.5)
    assert r.v_M.shape == r.status.shape == (4, 3)
    for i in range(4):
        for j in range(3):
            one = impact.collide_line(M[i, 0], 1.0, v_M[j], -1.0, 0.5)
            assert r.v_M[i, j] == one.v_M and r.J[i, j] == one.J


def test_vectors_broadcast_over_their_leading_axes_and_keep_their_components_last():
    v_M = np.random.default_rng(3).normal(0, 1, (2, 5, 3))
    r = impact.collide(1.0, 2.0, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], v_M, [0.0, 0.0, 0.0], 0.5)
    assert r.v_M.shape == (2, 5, 3) and r.status.shape == (2, 5)
    one = impact.collide(1.0, 2.0, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], v_M[1, 4], [0.0, 0.0, 0.0], 0.5)
    assert np.array_equal(r.v_M[1, 4], one.v_M) and r.status[1, 4] == one.status


def test_every_layout_gives_the_same_results():
    rng = np.random.default_rng(4)
    M, m, C_M, C_m, v_M, v_m, eps = random_space(rng, 300, np.float64)
    r = impact.collide(M, m, C_M, C_m, v_M, v_m, eps)
    # The batch layout (each component contiguous), strided views, and one pair's scalars.
    fortran = impact.collide(M, m, np.asfortranarray(C_M), np.asfortranarray(C_m), np.asfortranarray(v_M),
                             np.asfortranarray(v_m), eps)
    wide = np.zeros((600, 3))
    wide[::2] = v_M
    strided = impact.collide(M, m, C_M, C_m, wide[::2], v_m, eps)
    for other in (fortran, strided):
        assert np.array_equal(r.v_M, other.v_M) and np.array_equal(r.v_m, other.v_m)
        assert np.array_equal(r.status, other.status)
    one = impact.collide(float(M[7]), float(m[7]), C_M[7], C_m[7], v_M[7], v_m[7], float(eps[7]))
    assert np.array_equal(one.v_M, r.v_M[7]) and one.status == r.status[7]


def test_unaligned_and_byte_swapped_arrays_give_the_same_results():
    M, m, v_M, v_m, eps = random_line(np.random.default_rng(5), 100, np.float64)
    r = impact.collide_line(M, m, v_M, v_m, eps)
    unaligned = np.frombuffer(b"\0" + v_M.tobytes(), dtype=np.float64, offset=1)
    assert not unaligned.flags.aligned
    swapped = M.astype(">f8")
    other = impact.collide_line(swapped, m, unaligned, v_m, eps)
    assert np.array_equal(r.v_M, other.v_M) and np.array_equal(r.J, other.J)
    one = impact.collide_line(M[:1], m[0], unaligned[:1], v_m[0], eps[0])
    assert one.v_m[0] == r.v_m[0]


def test_inputs_are_not_changed():
    v_M = np.array([[1.0, 0.0]])
    kept = v_M.copy()
    impact.collide(1.0, 1.0, [0.0, 0.0], [1.0, 0.0], v_M, [0.0, 0.0], 1.0)
    assert np.array_equal(v_M, kept)


def test_float32_arrays_give_float32_and_anything_wider_float64():
    x32 = np.ones(3, dtype=np.float32)
    assert impact.collide_line(x32, 1.0, x32, -1.0, 0.5).v_M.dtype == np.float32   # Python floats follow
    assert impact.collide_line(x32, np.ones(3), x32, -1.0, 0.5).v_M.dtype == np.float64
    assert impact.collide_line(np.ones(3, dtype=np.int64), 1, 1, -1, 0.5).v_M.dtype == np.float64
    assert impact.collide_line(1.0, 1.0, 1.0, -1.0, 0.5).v_M.dtype == np.float64
    # float32 results are the float32 kernel's, not float64's rounded.
    r32 = impact.collide_line(np.float32(3.0), np.float32(7.0), np.float32(0.1), np.float32(-0.3), np.float32(0.3))
    assert isinstance(r32.v_m, np.float32)


def test_one_pair_gives_numpy_scalars_and_no_pairs_empty_arrays():
    r = impact.collide_line(1.0, 1.0, 1.0, -1.0, 1.0)
    assert np.ndim(r.v_M) == 0 and np.ndim(r.status) == 0
    empty = impact.collide(np.ones(0), 1.0, np.zeros((0, 2)), [1.0, 0.0], [1.0, 0.0], [0.0, 0.0], 1.0)
    assert empty.v_M.shape == (0, 2) and empty.status.shape == (0,)


def test_keywords_name_the_parameters():
    a = impact.collide_line(1.0, 2.0, 1.0, -1.0, 0.5)
    b = impact.collide_line(eps=0.5, v_m=-1.0, v_M=1.0, m=2.0, M=1.0)
    assert a == b


# ---------------------------------------------------------------------------------------------
# Bad input: an error that names the argument.

def test_a_vector_of_the_wrong_length_is_a_value_error_naming_it():
    with pytest.raises(ValueError, match="'v_m'.*3 components.*shape \\(4, 2\\)"):
        impact.collide(1.0, 1.0, np.zeros((4, 3)), [1.0, 0.0, 0.0], [1.0, 0.0, 0.0], np.zeros((4, 2)), 1.0)
    with pytest.raises(ValueError, match="'C_M'.*2 or 3 components"):
        impact.collide(1.0, 1.0, np.zeros(4), [1.0, 0.0], [1.0, 0.0], [0.0, 0.0], 1.0)


def test_shapes_that_do_not_broadcast_are_a_value_error_naming_both():
    with pytest.raises(ValueError, match="'v_M'.*\\(4,\\).*\\(5,\\).*'M'"):
        impact.collide_line(np.ones(5), 1.0, np.ones(4), 0.0, 1.0)


def test_a_dtype_that_is_not_real_is_a_type_error_naming_the_argument():
    with pytest.raises(TypeError, match="'eps'.*complex128"):
        impact.collide_line(1.0, 1.0, 1.0, -1.0, 0.5 + 1j)
    with pytest.raises(TypeError, match="'M'"):
        impact.collide_line("heavy", 1.0, 1.0, -1.0, 0.5)


def test_missing_or_unknown_arguments_are_type_errors():
    with pytest.raises(TypeError, match="missing argument 'eps'"):
        impact.collide_line(1.0, 1.0, 1.0, -1.0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'e'"):
        impact.collide_line(1.0, 1.0, 1.0, -1.0, e=0.5)
    with pytest.raises(TypeError, match="multiple values for argument 'M'"):
        impact.collide_line(1.0, 1.0, 1.0, -1.0, 0.5, M=2.0)
    with pytest.raises(TypeError, match="fast must be True or False"):
        impact.collide_line(1.0, 1.0, 1.0, -1.0, 0.5, fast="yes")


# ---------------------------------------------------------------------------------------------
# Outputs the caller gives (out=), in place on the batch layout (impact.batch_arrays).

@needs_reference
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("fast", [False, True])
@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_in_place_on_batch_arrays_the_results_are_the_cxx_kernels_bit_for_bit(case, fast, dtype, tmp_path):
    name, function, draw, outputs, status = case
    inputs = draw(np.random.default_rng(63), 1000, dtype)
    expected, expected_status = reference(name, dtype, fast, inputs, outputs, status, tmp_path)
    dimension = next((x.shape[1] for x in inputs if x.ndim == 2), None)
    b = impact.batch_arrays(function, 1000, dimension=dimension, dtype=dtype)
    for array, values in zip(b.inputs, inputs):
        np.copyto(array, values)
    result = function(*b.inputs, out=b.out, fast=fast)
    fields = [result] if not status else list(result)
    # The fields are the arrays given: an output named after an input is that input's array.
    given = [b.out] if not status else list(b.out)
    assert all(f is g for f, g in zip(fields, given))
    got = components(fields[:-1] if status else fields)
    for k in range(outputs):
        assert same_bits(got[k], expected[k]), f"{name} output component {k} in place differs from the C++ kernel"
    if status:
        assert np.array_equal(result.status, expected_status)
    # Into arrays of np.empty, the inputs left as they were.
    kept = [x.copy() for x in inputs]
    out = [np.empty_like(np.asfortranarray(f)) for f in fields]
    again = function(*inputs, out=out[0] if not status else tuple(out), fast=fast)
    for k, column in enumerate(components([again] if not status else list(again)[:-1])):
        assert same_bits(column, expected[k])
    assert all(np.array_equal(x, y) for x, y in zip(inputs, kept))


def test_in_place_the_velocities_are_updated_as_eq_8_says():
    # Eq. 8 with M = 1, m = 3, v_M = 2, v_m = -2, eps = 1/2: J = M m/(M + m) (1 + eps)(v_M - v_m)
    # = 3/4 * 3/2 * 4 = 9/2; v_M' = 2 - 9/2 = -5/2, v_m' = -2 + 3/2 = -1/2 (all exact in binary).
    b = impact.batch_arrays("collide_line", 2)
    b.M[:], b.m[:], b.v_M[:], b.v_m[:], b.eps[:] = [1.0, 1.0], [3.0, 3.0], [2.0, -2.0], [-2.0, 2.0], [0.5, 0.5]
    r = impact.collide_line(*b.inputs, out=b.out)
    assert r.v_M is b.v_M and r.J is b.J and r.status is b.status
    # The second pair separates: refused, its velocities kept and J = 0.
    assert list(b.v_M) == [-2.5, -2.0] and list(b.v_m) == [-0.5, 2.0] and list(b.J) == [4.5, 0.0]
    assert list(b.status) == [impact.status.ok, impact.status.separating]


def test_batch_arrays_are_laid_out_as_the_cxx_batch_arrays():
    # common.hpp's rule: every component an array of its own, the first 64 bytes past a page
    # boundary, each next one 256 bytes further (modulo 4 KiB); the statuses after them.
    for dtype in (np.float64, np.float32):
        b = impact.batch_arrays(impact.collide, 1000, dimension=3, dtype=dtype)
        assert [a.shape for a in b.inputs] == [(1000,), (1000,)] + [(1000, 3)] * 4 + [(1000,)]
        assert b.out[0] is b.v_M and b.out[1] is b.v_m and b.out[2] is b.status
        columns = []
        for a in b.inputs:
            columns += [a] if a.ndim == 1 else [a[:, k] for k in range(3)]
        assert all(c.dtype == dtype and c.flags.c_contiguous and c.flags.writeable for c in columns)
        offsets = [c.ctypes.data % 4096 for c in columns] + [b.status.ctypes.data % 4096]
        assert offsets == [(64 + 256 * k) % 4096 for k in range(16)]
        assert b.status.dtype == np.int64 and b.status.shape == (1000,)
    line = impact.batch_arrays(impact.collide_line, 0)
    assert line.J.shape == (0,) and len(line.out) == 4 and line.out[2] is line.J
    loss = impact.batch_arrays(impact.energy_loss, 5)
    assert loss.out is loss.dE and loss.dE.shape == (5,)


def test_a_kernel_returning_a_scalar_writes_into_the_array_given():
    M, m, v_M, v_m, eps = random_line(np.random.default_rng(7), 50, np.float64)
    out = np.empty(50)
    assert impact.energy_loss(M, m, v_M, v_m, eps, out=out) is out
    assert np.array_equal(out, impact.energy_loss(M, m, v_M, v_m, eps))
    assert impact.energy_loss(M, m, v_M, v_m, eps, out=(out,)) is out


def test_one_pair_writes_into_arrays_of_no_axes():
    v_M, v_m, J, status = np.array(2.0), np.array(-2.0), np.empty(()), np.empty((), np.int64)
    impact.collide_line(1.0, 3.0, v_M, v_m, 0.5, out=(v_M, v_m, J, status))
    assert (float(v_M), float(v_m), float(J), int(status)) == (-2.5, -0.5, 4.5, impact.status.ok)


def test_outputs_that_cannot_be_written_are_errors_naming_them():
    n = 4
    M, m, v_M, v_m, eps = random_line(np.random.default_rng(8), n, np.float64)
    J, status = np.empty(n), np.empty(n, np.int64)
    a, b = v_M.copy(), v_m.copy()
    with pytest.raises(TypeError, match="out must be a tuple of 4 arrays.*v_M, v_m, J, status.*it has 3"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, J))
    with pytest.raises(TypeError, match="out must be a tuple.*of type dict"):
        impact.collide_line(M, m, a, b, eps, out={"v_M": a})
    with pytest.raises(TypeError, match="out 'J' must be a NumPy array; it is of type list"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, [0.0] * n, status))
    with pytest.raises(TypeError, match="out 'status' has dtype int32; it must be int64"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, J, status.astype(np.int32)))
    with pytest.raises(TypeError, match="out 'J' has dtype float32; it must be float64"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, J.astype(np.float32), status))
    with pytest.raises(ValueError, match=r"out 'J' has shape \(3,\); the call's pairs give \(4,\)"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, J[:3], status))
    frozen = J.copy()
    frozen.flags.writeable = False
    with pytest.raises(ValueError, match="out 'J' is read-only"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, frozen, status))
    with pytest.raises(ValueError, match="out 'J' must hold its values contiguous"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, np.empty(2 * n)[::2], status))
    # A vector's components must each be contiguous: (n, 3) in C order is not.
    C = np.zeros((n, 3))
    with pytest.raises(ValueError, match=r"out 'v_M' must hold each component's values contiguous.*order='F'"):
        impact.collide(1.0, 1.0, C, C, C, C, 1.0, out=(np.empty((n, 3)), np.empty((n, 3), order="F"), status))
    # A vector whose components overlap one another (each column written through its own
    # pointer), or all at one place.
    base = np.empty(n + 2)
    with pytest.raises(ValueError, match="out 'v_M' has components that overlap one another"):
        impact.collide(1.0, 1.0, C, C, C, C, 1.0, out=(np.lib.stride_tricks.as_strided(base, (n, 3), (8, 8)),
                                                       np.empty((n, 3), order="F"), status))
    with pytest.raises(ValueError, match="out 'v_M' has components that overlap one another"):
        impact.collide(1.0, 1.0, C, C, C, C, 1.0, out=(np.lib.stride_tricks.as_strided(base, (n, 3), (8, 0)),
                                                       np.empty((n, 3), order="F"), status))
    with pytest.raises(TypeError, match=r"out 'J' has dtype >f8 \(not in the machine's byte order\)"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, np.empty(n, ">f8"), status))
    # Overlaps: only an output with the very array of the input it updates.
    with pytest.raises(ValueError, match="out 'v_M' shares memory with argument 'v_m'"):
        impact.collide_line(M, m, a, b, eps, out=(b, np.empty(n), J, status))
    with pytest.raises(ValueError, match="out 'J' shares memory with argument 'eps'"):
        impact.collide_line(M, m, a, b, eps, out=(a, b, eps, status))
    with pytest.raises(ValueError, match="out 'v_m' shares memory with out 'v_M'"):
        impact.collide_line(M, m, v_M, v_m, eps, out=(a, a, J, status))
    with pytest.raises(ValueError, match="out 'v_M' shares memory with argument 'v_M'"):
        impact.collide_line(M, m, a[::-1], b, eps, out=(a, b, J, status))
    # Nothing was written by a refused call.
    assert np.array_equal(a, v_M) and np.array_equal(b, v_m)


def test_batch_arrays_refuses_what_it_cannot_lay_out():
    with pytest.raises(ValueError, match="'collide_plane' is none of the module's kernels"):
        impact.batch_arrays("collide_plane", 3)
    with pytest.raises(ValueError, match="collide has forms in dimensions 2 and 3; give dimension="):
        impact.batch_arrays(impact.collide, 3)
    with pytest.raises(ValueError, match="collide_line has no form in dimension 3"):
        impact.batch_arrays(impact.collide_line, 3, dimension=3)
    with pytest.raises(TypeError, match="dtype must be float32 or float64 in the machine's byte order; it is float16"):
        impact.batch_arrays(impact.collide_line, 3, dtype=np.float16)
    with pytest.raises(ValueError, match="count must be a whole number"):
        impact.batch_arrays(impact.collide_line, -1)
    with pytest.raises(TypeError, match="byte order; it is >f8"):
        impact.batch_arrays(impact.collide_line, 3, dtype=">f8")


def test_batch_arrays_name_every_array_and_keep_their_own_attributes():
    b = impact.batch_arrays(impact.collide_line, 3)
    assert b["v_M"] is b.v_M and list(b.fields) == ["M", "m", "v_M", "v_m", "eps", "J", "status"]
    with pytest.raises(AttributeError, match="has no array 'w'"):
        b.w


def test_in_place_on_an_input_of_one_pair_along_an_axis():
    # The same memory under another stride of an axis of one element is the same array.
    v = np.array([[1.0, 0.0, 0.0]], order="F")
    same = np.lib.stride_tricks.as_strided(v, (1, 3), (999 * 8, 8))
    ok = impact.collide(1.0, 1.0, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], v, [[0.0, 0.0, 0.0]], 1.0)
    status = np.empty(1, np.int64)
    w = np.zeros((1, 3), order="F")
    r = impact.collide(1.0, 1.0, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], v, w, 1.0, out=(same, w, status))
    assert np.array_equal(r.v_M, ok.v_M) and np.array_equal(w, ok.v_m)

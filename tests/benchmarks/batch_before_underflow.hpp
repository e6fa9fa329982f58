// The batch loops of collide in 2D and 3D as Impact generated them before kernels tested
// their arithmetic for underflow (status::underflow): output/kernels/impact/collide_2d.hpp
// and collide_3d.hpp of commit e5c571e, from `namespace detail` on, in a namespace of their
// own. Not a kernel to use: kept so that the benchmark times the loops before and after
// the test side by side, in one run (docs/design-kernels.md, "How the batch loops were shaped").
#pragma once

#include "impact/impact.hpp"

namespace impact::before_underflow {

namespace detail {

using impact::detail::crowded;
using impact::detail::smallest_divisor;

// The loop of collide_batch in 2D, without branches; inlined where it is called, so that a
// block's call runs one pass of 8 pairs.
template <class Real, bool with_status>
IMPACT_ALWAYS_INLINE void collide_batch_2d(std::size_t count, const Real* IMPACT_RESTRICT M_, const Real* IMPACT_RESTRICT m_, const Real* IMPACT_RESTRICT C_Mx_, const Real* IMPACT_RESTRICT C_My_, const Real* IMPACT_RESTRICT C_mx_, const Real* IMPACT_RESTRICT C_my_, Real* IMPACT_RESTRICT v_Mx_, Real* IMPACT_RESTRICT v_My_, Real* IMPACT_RESTRICT v_mx_, Real* IMPACT_RESTRICT v_my_, const Real* IMPACT_RESTRICT eps_, impact::status* IMPACT_RESTRICT status_) noexcept
{
    IMPACT_INDEPENDENT_ITERATIONS
    for (std::size_t i = 0; i < count; ++i) {
        // The status, as the scalar kernel decides it: the first guard that fails.
        // (x * 0 is 0 for a finite x and NaN otherwise: one sum tests many values.)
        impact::status outcome = status::ok;
        {
            bool fails = !(((std::fma(C_Mx_[i], Real(0), C_My_[i] * Real(0)) + std::fma(C_mx_[i], Real(0), C_my_[i] * Real(0))) + (std::fma(v_Mx_[i], Real(0), v_My_[i] * Real(0)) + std::fma(v_mx_[i], Real(0), v_my_[i] * Real(0)))) == Real(0));
            outcome = fails ? status::non_finite : outcome;
            fails = !(eps_[i] >= Real(0));
            fails |= !(eps_[i] <= Real(1));
            outcome = fails ? status::invalid_restitution : outcome;
            fails = !(M_[i] > Real(0));
            fails |= !(m_[i] > Real(0));
            fails |= !(std::fma(M_[i], Real(0), m_[i] * Real(0)) == Real(0));
            outcome = fails ? status::invalid_mass : outcome;
            const bool admitted = outcome == status::ok;
            impact::status condition = status::ok;
            const Real t0 = C_Mx_[i] - C_mx_[i];
            const Real t1 = t0 * t0;
            const Real t2 = C_My_[i] - C_my_[i];
            const Real t3 = t2 * t2;
            const Real t4 = t1 + t3;
            const Real t5 = v_Mx_[i] - v_mx_[i];
            const Real t6 = t0 * t5;
            const Real t7 = v_My_[i] - v_my_[i];
            const Real t8 = t2 * t7;
            const Real t9 = t6 + t8;
            fails = !(t9 < Real(0));
            condition = fails ? status::separating : condition;
            fails = !(t4 > Real(0));
            condition = fails ? status::coincident_centres : condition;
            outcome = admitted ? condition : outcome;
        }
        const bool resolved = outcome == status::ok;
        // Every pair is computed; one not resolved divides by 1, and its results are discarded.
        const Real M = M_[i];
        const Real m = m_[i];
        const Real C_Mx = C_Mx_[i];
        const Real C_My = C_My_[i];
        const Real C_mx = C_mx_[i];
        const Real C_my = C_my_[i];
        const Real v_Mx = v_Mx_[i];
        const Real v_My = v_My_[i];
        const Real v_mx = v_mx_[i];
        const Real v_my = v_my_[i];
        const Real eps = eps_[i];
        const Real t0 = C_Mx - C_mx;
        const Real t1 = t0 * t0;
        const Real t2 = C_My - C_my;
        const Real t3 = t2 * t2;
        const Real t4 = t1 + t3;
        const Real t5 = v_Mx - v_mx;
        const Real t6 = t0 * t5;
        const Real t7 = v_My - v_my;
        const Real t8 = t2 * t7;
        const Real t9 = t6 + t8;
        const Real t10 = Real(1) + eps;
        const Real t11 = t10 - Real(1);
        const Real t12 = t0 - C_Mx;
        const Real t13 = C_Mx - (t0 - t12) - (C_mx + t12);
        const Real t14 = t5 - v_Mx;
        const Real t15 = t2 - C_My;
        const Real t16 = C_My - (t2 - t15) - (C_my + t15);
        const Real t17 = t7 - v_My;
        const Real t18 = t9 - t6;
        const Real t19 = t6 - (t9 - t18) + (t8 - t18) + (std::fma(t13, t5, std::fma(t0, v_Mx - (t5 - t14) - (v_mx + t14), std::fma(t0, t5, -t6))) + std::fma(t16, t7, std::fma(t2, v_My - (t7 - t17) - (v_my + t17), std::fma(t2, t7, -t8))));
        const Real t20 = t9 + t19;
        const Real t21 = t10 * t20;
        const Real t22 = M + m;
        const Real t23 = t22 - M;
        const Real t24 = t4 - t1;
        const Real t25 = t1 - (t4 - t24) + (t3 - t24) + (std::fma(t13, t0, std::fma(t0, t13, std::fma(t0, t0, -t1))) + std::fma(t16, t2, std::fma(t2, t16, std::fma(t2, t2, -t3))));
        const Real t26 = t4 + t25;
        const Real t27 = t22 * t26;
        const bool usable = resolved && (std::fabs(t27) >= detail::smallest_divisor<Real>) && (std::fabs(t27) <= std::numeric_limits<Real>::max());
        const Real t28 = t21 / (usable ? t27 : Real(1));
        const Real t29 = -t28;
        const Real t30 = t28 + std::fma(t29, std::fma(M - (t22 - t23) + (m - t23), t26, std::fma(t22, t25 - (t26 - t4), std::fma(t22, t26, -t27))), std::fma(t29, t27, t21) + std::fma(Real(1) - (t10 - t11) + (eps - t11), t20, std::fma(t10, t19 - (t20 - t9), std::fma(t10, t20, -t21)))) / (usable ? t27 : Real(1));
        const Real t31 = t30 * m;
        const Real t32 = t30 * M;
        const Real v_Mx_out = -(t31 * t0) + v_Mx;
        const Real v_My_out = -(t31 * t2) + v_My;
        const Real v_mx_out = t32 * t0 + v_mx;
        const Real v_my_out = t32 * t2 + v_my;
        const bool written = usable && ((std::fma(v_Mx_out, Real(0), v_My_out * Real(0)) + std::fma(v_mx_out, Real(0), v_my_out * Real(0))) == Real(0));
        v_Mx_[i] = written ? v_Mx_out : v_Mx_[i];
        v_My_[i] = written ? v_My_out : v_My_[i];
        v_mx_[i] = written ? v_mx_out : v_mx_[i];
        v_my_[i] = written ? v_my_out : v_my_[i];
        if constexpr (with_status)
            status_[i] = resolved && !written ? status::out_of_range : outcome;
    }
}

// collide_batch_2d over blocks of 8 pairs, each array's data asked for 64 pairs ahead: the
// processor's own prefetching, following so many arrays, falls behind.
template <class Real, bool with_status>
inline void collide_batch_2d_ahead(std::size_t count, const Real* IMPACT_RESTRICT M_, const Real* IMPACT_RESTRICT m_, const Real* IMPACT_RESTRICT C_Mx_, const Real* IMPACT_RESTRICT C_My_, const Real* IMPACT_RESTRICT C_mx_, const Real* IMPACT_RESTRICT C_my_, Real* IMPACT_RESTRICT v_Mx_, Real* IMPACT_RESTRICT v_My_, Real* IMPACT_RESTRICT v_mx_, Real* IMPACT_RESTRICT v_my_, const Real* IMPACT_RESTRICT eps_, impact::status* IMPACT_RESTRICT status_) noexcept
{
    constexpr std::size_t block = 8, ahead = 64;
    std::size_t b = 0;
    for (; b + block <= count; b += block) {
        if (b + ahead < count) {
            IMPACT_PREFETCH(M_ + b + ahead, 0);
            IMPACT_PREFETCH(m_ + b + ahead, 0);
            IMPACT_PREFETCH(C_Mx_ + b + ahead, 0);
            IMPACT_PREFETCH(C_My_ + b + ahead, 0);
            IMPACT_PREFETCH(C_mx_ + b + ahead, 0);
            IMPACT_PREFETCH(C_my_ + b + ahead, 0);
            IMPACT_PREFETCH(v_Mx_ + b + ahead, 1);
            IMPACT_PREFETCH(v_My_ + b + ahead, 1);
            IMPACT_PREFETCH(v_mx_ + b + ahead, 1);
            IMPACT_PREFETCH(v_my_ + b + ahead, 1);
            IMPACT_PREFETCH(eps_ + b + ahead, 0);
            if constexpr (with_status)
                IMPACT_PREFETCH(status_ + b + ahead, 1);
        }
        collide_batch_2d<Real, with_status>(block, M_ + b, m_ + b, C_Mx_ + b, C_My_ + b, C_mx_ + b, C_my_ + b, v_Mx_ + b, v_My_ + b, v_mx_ + b, v_my_ + b, eps_ + b, with_status ? status_ + b : status_);
    }
    collide_batch_2d<Real, with_status>(count - b, M_ + b, m_ + b, C_Mx_ + b, C_My_ + b, C_mx_ + b, C_my_ + b, v_Mx_ + b, v_My_ + b, v_mx_ + b, v_my_ + b, eps_ + b, with_status ? status_ + b : status_);
}

} // namespace detail

/// collide over `count` collisions stored as structure of arrays: outputs named after
/// inputs are updated in place. `status` (if not null) receives each status.
/// The loop has no branches, so that compilers vectorise it; each result is bit for
/// bit the scalar collide's (compiled alike, e.g. -ffp-contract=off). The arrays written
/// must not overlap any other array.
template <class Real>
inline void collide_batch(const collide_batch_data<Real, 2>& data) noexcept
{
    if (data.status)
        detail::collide_batch_2d_ahead<Real, true>(data.count, data.M, data.m, data.C_M[0], data.C_M[1], data.C_m[0], data.C_m[1], data.v_M[0], data.v_M[1], data.v_m[0], data.v_m[1], data.eps, data.status);
    else
        detail::collide_batch_2d_ahead<Real, false>(data.count, data.M, data.m, data.C_M[0], data.C_M[1], data.C_m[0], data.C_m[1], data.v_M[0], data.v_M[1], data.v_m[0], data.v_m[1], data.eps, nullptr);
}

namespace detail {

using impact::detail::crowded;
using impact::detail::smallest_divisor;

// The loop of collide_batch in 3D, without branches; inlined where it is called, so that a
// block's call runs one pass of 8 pairs.
template <class Real, bool with_status>
IMPACT_ALWAYS_INLINE void collide_batch_3d(std::size_t count, const Real* IMPACT_RESTRICT M_, const Real* IMPACT_RESTRICT m_, const Real* IMPACT_RESTRICT C_Mx_, const Real* IMPACT_RESTRICT C_My_, const Real* IMPACT_RESTRICT C_Mz_, const Real* IMPACT_RESTRICT C_mx_, const Real* IMPACT_RESTRICT C_my_, const Real* IMPACT_RESTRICT C_mz_, Real* IMPACT_RESTRICT v_Mx_, Real* IMPACT_RESTRICT v_My_, Real* IMPACT_RESTRICT v_Mz_, Real* IMPACT_RESTRICT v_mx_, Real* IMPACT_RESTRICT v_my_, Real* IMPACT_RESTRICT v_mz_, const Real* IMPACT_RESTRICT eps_, impact::status* IMPACT_RESTRICT status_) noexcept
{
    IMPACT_INDEPENDENT_ITERATIONS
    for (std::size_t i = 0; i < count; ++i) {
        // The status, as the scalar kernel decides it: the first guard that fails.
        // (x * 0 is 0 for a finite x and NaN otherwise: one sum tests many values.)
        impact::status outcome = status::ok;
        {
            bool fails = !((((std::fma(C_Mx_[i], Real(0), C_My_[i] * Real(0)) + std::fma(C_Mz_[i], Real(0), C_mx_[i] * Real(0))) + (std::fma(C_my_[i], Real(0), C_mz_[i] * Real(0)) + std::fma(v_Mx_[i], Real(0), v_My_[i] * Real(0)))) + (std::fma(v_Mz_[i], Real(0), v_mx_[i] * Real(0)) + std::fma(v_my_[i], Real(0), v_mz_[i] * Real(0)))) == Real(0));
            outcome = fails ? status::non_finite : outcome;
            fails = !(eps_[i] >= Real(0));
            fails |= !(eps_[i] <= Real(1));
            outcome = fails ? status::invalid_restitution : outcome;
            fails = !(M_[i] > Real(0));
            fails |= !(m_[i] > Real(0));
            fails |= !(std::fma(M_[i], Real(0), m_[i] * Real(0)) == Real(0));
            outcome = fails ? status::invalid_mass : outcome;
            const bool admitted = outcome == status::ok;
            impact::status condition = status::ok;
            const Real t0 = C_Mx_[i] - C_mx_[i];
            const Real t1 = t0 * t0;
            const Real t2 = C_My_[i] - C_my_[i];
            const Real t3 = t2 * t2;
            const Real t4 = t1 + t3;
            const Real t5 = C_Mz_[i] - C_mz_[i];
            const Real t6 = t5 * t5;
            const Real t7 = v_Mx_[i] - v_mx_[i];
            const Real t8 = t0 * t7;
            const Real t9 = v_My_[i] - v_my_[i];
            const Real t10 = t2 * t9;
            const Real t11 = t8 + t10;
            const Real t12 = v_Mz_[i] - v_mz_[i];
            const Real t13 = t5 * t12;
            fails = !(t11 + t13 < Real(0));
            condition = fails ? status::separating : condition;
            fails = !(t4 + t6 > Real(0));
            condition = fails ? status::coincident_centres : condition;
            outcome = admitted ? condition : outcome;
        }
        const bool resolved = outcome == status::ok;
        // Every pair is computed; one not resolved divides by 1, and its results are discarded.
        const Real M = M_[i];
        const Real m = m_[i];
        const Real C_Mx = C_Mx_[i];
        const Real C_My = C_My_[i];
        const Real C_Mz = C_Mz_[i];
        const Real C_mx = C_mx_[i];
        const Real C_my = C_my_[i];
        const Real C_mz = C_mz_[i];
        const Real v_Mx = v_Mx_[i];
        const Real v_My = v_My_[i];
        const Real v_Mz = v_Mz_[i];
        const Real v_mx = v_mx_[i];
        const Real v_my = v_my_[i];
        const Real v_mz = v_mz_[i];
        const Real eps = eps_[i];
        const Real t0 = C_Mx - C_mx;
        const Real t1 = t0 - C_Mx;
        const Real t2 = t0 * t0;
        const Real t3 = C_Mx - (t0 - t1) - (C_mx + t1);
        const Real t4 = C_My - C_my;
        const Real t5 = t4 - C_My;
        const Real t6 = t4 * t4;
        const Real t7 = t2 + t6;
        const Real t8 = t7 - t2;
        const Real t9 = C_My - (t4 - t5) - (C_my + t5);
        const Real t10 = t2 - (t7 - t8) + (t6 - t8) + (std::fma(t3, t0, std::fma(t0, t3, std::fma(t0, t0, -t2))) + std::fma(t9, t4, std::fma(t4, t9, std::fma(t4, t4, -t6))));
        const Real t11 = t7 + t10;
        const Real t12 = C_Mz - C_mz;
        const Real t13 = t12 - C_Mz;
        const Real t14 = t12 * t12;
        const Real t15 = t11 + t14;
        const Real t16 = t15 - t11;
        const Real t17 = C_Mz - (t12 - t13) - (C_mz + t13);
        const Real t18 = t11 - (t15 - t16) + (t14 - t16) + (t10 - (t11 - t7) + std::fma(t17, t12, std::fma(t12, t17, std::fma(t12, t12, -t14))));
        const Real t19 = t15 + t18;
        const Real t20 = v_Mx - v_mx;
        const Real t21 = t0 * t20;
        const Real t22 = t20 - v_Mx;
        const Real t23 = v_My - v_my;
        const Real t24 = t4 * t23;
        const Real t25 = t21 + t24;
        const Real t26 = t25 - t21;
        const Real t27 = t23 - v_My;
        const Real t28 = t21 - (t25 - t26) + (t24 - t26) + (std::fma(t3, t20, std::fma(t0, v_Mx - (t20 - t22) - (v_mx + t22), std::fma(t0, t20, -t21))) + std::fma(t9, t23, std::fma(t4, v_My - (t23 - t27) - (v_my + t27), std::fma(t4, t23, -t24))));
        const Real t29 = t25 + t28;
        const Real t30 = v_Mz - v_mz;
        const Real t31 = t12 * t30;
        const Real t32 = t29 + t31;
        const Real t33 = t32 - t29;
        const Real t34 = t30 - v_Mz;
        const Real t35 = t29 - (t32 - t33) + (t31 - t33) + (t28 - (t29 - t25) + std::fma(t17, t30, std::fma(t12, v_Mz - (t30 - t34) - (v_mz + t34), std::fma(t12, t30, -t31))));
        const Real t36 = t32 + t35;
        const Real t37 = Real(1) + eps;
        const Real t38 = t37 * t36;
        const Real t39 = t37 - Real(1);
        const Real t40 = M + m;
        const Real t41 = t40 * t19;
        const bool usable = resolved && (std::fabs(t41) >= detail::smallest_divisor<Real>) && (std::fabs(t41) <= std::numeric_limits<Real>::max());
        const Real t42 = t38 / (usable ? t41 : Real(1));
        const Real t43 = t40 - M;
        const Real t44 = -t42;
        const Real t45 = t42 + std::fma(t44, std::fma(M - (t40 - t43) + (m - t43), t19, std::fma(t40, t18 - (t19 - t15), std::fma(t40, t19, -t41))), std::fma(t44, t41, t38) + std::fma(Real(1) - (t37 - t39) + (eps - t39), t36, std::fma(t37, t35 - (t36 - t32), std::fma(t37, t36, -t38)))) / (usable ? t41 : Real(1));
        const Real t46 = t45 * m;
        const Real t47 = t45 * M;
        const Real v_Mx_out = -(t46 * t0) + v_Mx;
        const Real v_My_out = -(t46 * t4) + v_My;
        const Real v_Mz_out = -(t46 * t12) + v_Mz;
        const Real v_mx_out = t47 * t0 + v_mx;
        const Real v_my_out = t47 * t4 + v_my;
        const Real v_mz_out = t47 * t12 + v_mz;
        const Real finite0 = std::fma(v_Mx_out, Real(0), v_My_out * Real(0));
        const Real finite1 = std::fma(v_Mz_out, Real(0), v_mx_out * Real(0));
        const Real finite2 = std::fma(v_my_out, Real(0), v_mz_out * Real(0));
        const Real finite3 = finite0 + finite1;
        const Real finite4 = finite3 + finite2;
        const bool written = usable && (finite4 == Real(0));
        v_Mx_[i] = written ? v_Mx_out : v_Mx_[i];
        v_My_[i] = written ? v_My_out : v_My_[i];
        v_Mz_[i] = written ? v_Mz_out : v_Mz_[i];
        v_mx_[i] = written ? v_mx_out : v_mx_[i];
        v_my_[i] = written ? v_my_out : v_my_[i];
        v_mz_[i] = written ? v_mz_out : v_mz_[i];
        if constexpr (with_status)
            status_[i] = resolved && !written ? status::out_of_range : outcome;
    }
}

// collide_batch_3d over blocks of 8 pairs, each array's data asked for 64 pairs ahead: the
// processor's own prefetching, following so many arrays, falls behind.
template <class Real, bool with_status>
inline void collide_batch_3d_ahead(std::size_t count, const Real* IMPACT_RESTRICT M_, const Real* IMPACT_RESTRICT m_, const Real* IMPACT_RESTRICT C_Mx_, const Real* IMPACT_RESTRICT C_My_, const Real* IMPACT_RESTRICT C_Mz_, const Real* IMPACT_RESTRICT C_mx_, const Real* IMPACT_RESTRICT C_my_, const Real* IMPACT_RESTRICT C_mz_, Real* IMPACT_RESTRICT v_Mx_, Real* IMPACT_RESTRICT v_My_, Real* IMPACT_RESTRICT v_Mz_, Real* IMPACT_RESTRICT v_mx_, Real* IMPACT_RESTRICT v_my_, Real* IMPACT_RESTRICT v_mz_, const Real* IMPACT_RESTRICT eps_, impact::status* IMPACT_RESTRICT status_) noexcept
{
    constexpr std::size_t block = 8, ahead = 64;
    std::size_t b = 0;
    for (; b + block <= count; b += block) {
        if (b + ahead < count) {
            IMPACT_PREFETCH(M_ + b + ahead, 0);
            IMPACT_PREFETCH(m_ + b + ahead, 0);
            IMPACT_PREFETCH(C_Mx_ + b + ahead, 0);
            IMPACT_PREFETCH(C_My_ + b + ahead, 0);
            IMPACT_PREFETCH(C_Mz_ + b + ahead, 0);
            IMPACT_PREFETCH(C_mx_ + b + ahead, 0);
            IMPACT_PREFETCH(C_my_ + b + ahead, 0);
            IMPACT_PREFETCH(C_mz_ + b + ahead, 0);
            IMPACT_PREFETCH(v_Mx_ + b + ahead, 1);
            IMPACT_PREFETCH(v_My_ + b + ahead, 1);
            IMPACT_PREFETCH(v_Mz_ + b + ahead, 1);
            IMPACT_PREFETCH(v_mx_ + b + ahead, 1);
            IMPACT_PREFETCH(v_my_ + b + ahead, 1);
            IMPACT_PREFETCH(v_mz_ + b + ahead, 1);
            IMPACT_PREFETCH(eps_ + b + ahead, 0);
            if constexpr (with_status)
                IMPACT_PREFETCH(status_ + b + ahead, 1);
        }
        collide_batch_3d<Real, with_status>(block, M_ + b, m_ + b, C_Mx_ + b, C_My_ + b, C_Mz_ + b, C_mx_ + b, C_my_ + b, C_mz_ + b, v_Mx_ + b, v_My_ + b, v_Mz_ + b, v_mx_ + b, v_my_ + b, v_mz_ + b, eps_ + b, with_status ? status_ + b : status_);
    }
    collide_batch_3d<Real, with_status>(count - b, M_ + b, m_ + b, C_Mx_ + b, C_My_ + b, C_Mz_ + b, C_mx_ + b, C_my_ + b, C_mz_ + b, v_Mx_ + b, v_My_ + b, v_Mz_ + b, v_mx_ + b, v_my_ + b, v_mz_ + b, eps_ + b, with_status ? status_ + b : status_);
}

// collide_batch_3d over blocks of 8 pairs for arrays that start at one offset within their pages:
// pair i of every array then falls on the same cache sets. The read-only array k is read
// 2 (k + 1) blocks ahead of its turn, into a ring of blocks, so that the arrays are read
// at offsets 128 bytes apart, as if staggered.
template <class Real, bool with_status>
inline void collide_batch_3d_skewed(std::size_t count, const Real* IMPACT_RESTRICT M_, const Real* IMPACT_RESTRICT m_, const Real* IMPACT_RESTRICT C_Mx_, const Real* IMPACT_RESTRICT C_My_, const Real* IMPACT_RESTRICT C_Mz_, const Real* IMPACT_RESTRICT C_mx_, const Real* IMPACT_RESTRICT C_my_, const Real* IMPACT_RESTRICT C_mz_, Real* IMPACT_RESTRICT v_Mx_, Real* IMPACT_RESTRICT v_My_, Real* IMPACT_RESTRICT v_Mz_, Real* IMPACT_RESTRICT v_mx_, Real* IMPACT_RESTRICT v_my_, Real* IMPACT_RESTRICT v_mz_, const Real* IMPACT_RESTRICT eps_, impact::status* IMPACT_RESTRICT status_) noexcept
{
    constexpr std::size_t block = 8, ahead = 64, ring = 32, read_only = 9;
    const Real* const from[read_only] = {M_, m_, C_Mx_, C_My_, C_Mz_, C_mx_, C_my_, C_mz_, eps_};
    alignas(64) Real stage[read_only][ring][block];
    auto lead = [](std::size_t k) { return 2 * (k + 1); };
    auto read = [&](std::size_t k, std::size_t j) {
        for (std::size_t i = 0; i < block; ++i)
            stage[k][j % ring][i] = from[k][j * block + i];
    };
    const std::size_t blocks = count / block;
    for (std::size_t k = 0; k < read_only; ++k)
        for (std::size_t j = 0; j < lead(k) && j < blocks; ++j)
            read(k, j);
    std::size_t b = 0;
    for (std::size_t j = 0; j < blocks; ++j, b += block) {
        if (b + ahead < count) {
            if (b + ahead + block * lead(0) < count)
                IMPACT_PREFETCH(M_ + b + ahead + block * lead(0), 0);
            if (b + ahead + block * lead(1) < count)
                IMPACT_PREFETCH(m_ + b + ahead + block * lead(1), 0);
            if (b + ahead + block * lead(2) < count)
                IMPACT_PREFETCH(C_Mx_ + b + ahead + block * lead(2), 0);
            if (b + ahead + block * lead(3) < count)
                IMPACT_PREFETCH(C_My_ + b + ahead + block * lead(3), 0);
            if (b + ahead + block * lead(4) < count)
                IMPACT_PREFETCH(C_Mz_ + b + ahead + block * lead(4), 0);
            if (b + ahead + block * lead(5) < count)
                IMPACT_PREFETCH(C_mx_ + b + ahead + block * lead(5), 0);
            if (b + ahead + block * lead(6) < count)
                IMPACT_PREFETCH(C_my_ + b + ahead + block * lead(6), 0);
            if (b + ahead + block * lead(7) < count)
                IMPACT_PREFETCH(C_mz_ + b + ahead + block * lead(7), 0);
            IMPACT_PREFETCH(v_Mx_ + b + ahead, 1);
            IMPACT_PREFETCH(v_My_ + b + ahead, 1);
            IMPACT_PREFETCH(v_Mz_ + b + ahead, 1);
            IMPACT_PREFETCH(v_mx_ + b + ahead, 1);
            IMPACT_PREFETCH(v_my_ + b + ahead, 1);
            IMPACT_PREFETCH(v_mz_ + b + ahead, 1);
            if (b + ahead + block * lead(8) < count)
                IMPACT_PREFETCH(eps_ + b + ahead + block * lead(8), 0);
            if constexpr (with_status)
                IMPACT_PREFETCH(status_ + b + ahead, 1);
        }
        for (std::size_t k = 0; k < read_only; ++k)
            if (j + lead(k) < blocks)
                read(k, j + lead(k));
        const std::size_t r = j % ring;
        collide_batch_3d<Real, with_status>(block, stage[0][r], stage[1][r], stage[2][r], stage[3][r], stage[4][r], stage[5][r], stage[6][r], stage[7][r], v_Mx_ + b, v_My_ + b, v_Mz_ + b, v_mx_ + b, v_my_ + b, v_mz_ + b, stage[8][r], with_status ? status_ + b : status_);
    }
    collide_batch_3d<Real, with_status>(count - b, M_ + b, m_ + b, C_Mx_ + b, C_My_ + b, C_Mz_ + b, C_mx_ + b, C_my_ + b, C_mz_ + b, v_Mx_ + b, v_My_ + b, v_Mz_ + b, v_mx_ + b, v_my_ + b, v_mz_ + b, eps_ + b, with_status ? status_ + b : status_);
}

} // namespace detail

/// collide over `count` collisions stored as structure of arrays: outputs named after
/// inputs are updated in place. `status` (if not null) receives each status.
/// The loop has no branches, so that compilers vectorise it; each result is bit for
/// bit the scalar collide's (compiled alike, e.g. -ffp-contract=off). The arrays written
/// must not overlap any other array.
template <class Real>
inline void collide_batch(const collide_batch_data<Real, 3>& data) noexcept
{
    // Arrays of doubles that crowd one page offset are read skewed (the blocks and the
    // distances are a double's; other types keep the plain loop).
    if constexpr (sizeof(Real) == sizeof(double))
        if (detail::crowded(std::array<const void*, 9>{data.M, data.m, data.C_M[0], data.C_M[1], data.C_M[2], data.C_m[0], data.C_m[1], data.C_m[2], data.eps})) {
            if (data.status)
                detail::collide_batch_3d_skewed<Real, true>(data.count, data.M, data.m, data.C_M[0], data.C_M[1], data.C_M[2], data.C_m[0], data.C_m[1], data.C_m[2], data.v_M[0], data.v_M[1], data.v_M[2], data.v_m[0], data.v_m[1], data.v_m[2], data.eps, data.status);
            else
                detail::collide_batch_3d_skewed<Real, false>(data.count, data.M, data.m, data.C_M[0], data.C_M[1], data.C_M[2], data.C_m[0], data.C_m[1], data.C_m[2], data.v_M[0], data.v_M[1], data.v_M[2], data.v_m[0], data.v_m[1], data.v_m[2], data.eps, nullptr);
            return;
        }
    if (data.status)
        detail::collide_batch_3d_ahead<Real, true>(data.count, data.M, data.m, data.C_M[0], data.C_M[1], data.C_M[2], data.C_m[0], data.C_m[1], data.C_m[2], data.v_M[0], data.v_M[1], data.v_M[2], data.v_m[0], data.v_m[1], data.v_m[2], data.eps, data.status);
    else
        detail::collide_batch_3d_ahead<Real, false>(data.count, data.M, data.m, data.C_M[0], data.C_M[1], data.C_M[2], data.C_m[0], data.C_m[1], data.C_m[2], data.v_M[0], data.v_M[1], data.v_M[2], data.v_m[0], data.v_m[1], data.v_m[2], data.eps, nullptr);
}

} // namespace impact::before_underflow

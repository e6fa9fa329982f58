// Speed of the generated collision kernels, side by side in one run with a hand-written
// batch loop of the same arithmetic, the batch loop as generated before the kernels tested
// their arithmetic for underflow (batch_before_underflow.hpp), the fast form's batch
// (impact::fast), the plain loop a user would write instead (no guards, no compensated
// arithmetic), the fast form's contract written by hand beside it (the same update with the
// guards, statuses and range test; and with the guards and statuses alone, a floor under what
// the contract costs), and a memory-bandwidth probe (a triad).
//
// A benchmark, never a test: it reports collisions per second of the scalar and batch
// kernels, in cache (4 096 pairs) and out of cache (4 194 304 pairs), and the ratios the
// kernels are held to: batch / hand-written, and bytes per second of the batch out of
// cache / triad. The loops are timed side by side: each iteration of a benchmark makes one
// pass of every loop (scalar, batch, hand-written, triad) over data of the same layout, in
// an order that turns from one iteration to the next, and each repetition reports its own
// ratios. The memory's bandwidth on a shared machine drifts by a third within minutes;
// loops timed a pass apart see the same machine, loops timed seconds apart do not.
// Every pass starts from the same approaching pairs (velocities are reset, untimed),
// since a resolved pair separates and would take the kernel's early exit next time.
// Out of cache, the caches are flushed before each pass, untimed too: the reset's writes,
// left in them, would be written back during the next pass and counted against it.
//
// Out of cache, the data are laid out three ways:
// - 4 KiB pages, every array at the same offset within its page, as arrays allocated one
//   by one are (a large allocation starts at a page boundary plus a fixed header). The 16
//   arrays of a 3D batch then fall on the same cache sets, pair for pair, and the loops
//   lose about a fifth of their speed, the hand-written one as much as the generated one;
// - 4 KiB pages, array k starting 64 + 256 k bytes (modulo 4 KiB) past a page boundary, as
//   docs/kernels.md recommends for large batches (in cache too);
// - the same on 2 MiB pages (madvise MADV_HUGEPAGE): fewer misses of address translation.
// The triad's three arrays are laid out alike.

#include "batch_before_underflow.hpp"
#include "machine.hpp"
#include "impact/impact.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <new>
#include <random>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <sys/mman.h>

namespace {

constexpr std::size_t in_cache = 4096;
constexpr std::size_t out_of_cache = 4194304;

// The size of the pages an array is on, in KiB (the benchmarks' second argument).
constexpr std::size_t small_pages = 4, huge_pages = 2048;

// Where the arrays of a batch start within their pages (the benchmarks' third argument).
enum layout : std::int64_t { same_offset, staggered };

// Bytes held now by arrays that asked for 2 MiB pages.
std::size_t huge_bytes_asked = 0;

// Arrays aligned to 64 bytes, as data for SIMD loops are (with std::vector's own 16,
// every 512-bit load straddles two cache lines), and `offset` bytes past the start of a
// page: of a 4 KiB page, or, for `huge` arrays, of a 2 MiB page, for which the allocator
// asks the kernel (madvise, which it may decline: see huge_pages_granted).
template <class T>
struct aligned {
    using value_type = T;
    static constexpr std::size_t small_page = 4096, huge_page = std::size_t{2} << 20;
    bool huge = false;
    std::size_t offset = 0;
    // An array assigned another takes its pages along.
    using propagate_on_container_copy_assignment = std::true_type;
    using propagate_on_container_move_assignment = std::true_type;
    using propagate_on_container_swap = std::true_type;
    aligned() = default;
    aligned(bool on_huge_pages, std::size_t offset_in_page) noexcept : huge(on_huge_pages), offset(offset_in_page) {}
    template <class U>
    aligned(const aligned<U>& other) noexcept : huge(other.huge), offset(other.offset) {}
    std::size_t page() const { return huge ? huge_page : small_page; }
    std::size_t bytes(std::size_t n) const { return (offset + n * sizeof(T) + page() - 1) / page() * page(); }
    T* allocate(std::size_t n)
    {
        char* start = static_cast<char*>(::operator new(bytes(n), std::align_val_t{page()}));
        if (huge) {
            madvise(start, bytes(n), MADV_HUGEPAGE);
            huge_bytes_asked += bytes(n);
        }
        return reinterpret_cast<T*>(start + offset);
    }
    void deallocate(T* p, std::size_t n) noexcept
    {
        if (huge)
            huge_bytes_asked -= bytes(n);
        ::operator delete(reinterpret_cast<char*>(p) - offset, std::align_val_t{page()});
    }
    template <class U>
    bool operator==(const aligned<U>& other) const noexcept { return huge == other.huge && offset == other.offset; }
    template <class U>
    bool operator!=(const aligned<U>& other) const noexcept { return !(*this == other); }
};
template <class T>
using array_of = std::vector<T, aligned<T>>;

// Allocators for the arrays of one batch, in turn: the k-th array starts 64 bytes past a
// page boundary (same_offset, as a large allocation's header puts it), or 64 + 256 k bytes
// modulo 4 KiB (staggered).
class arrays_laid_out {
public:
    arrays_laid_out(bool huge, layout how) : huge_(huge), how_(how) {}
    aligned<double> next()
    {
        const std::size_t k = count_++;
        return aligned<double>(huge_, how_ == staggered ? (64 + 256 * k) % 4096 : 64);
    }

private:
    bool huge_;
    layout how_;
    std::size_t count_ = 0;
};

template <std::size_t D>
struct pairs {
    std::size_t count = 0;
    array_of<double> M, m, eps;
    std::array<array_of<double>, D> C_M, C_m, v_M, v_m, v_M0, v_m0;
    array_of<impact::status> status;

    pairs(std::size_t n, bool huge, layout how) : count(n)
    {
        arrays_laid_out arrays(huge, how);
        for (array_of<double>* a : {&M, &m, &eps})
            *a = array_of<double>(n, arrays.next());
        for (auto* vectors : {&C_M, &C_m, &v_M, &v_m})
            for (auto& v : *vectors)
                v = array_of<double>(n, arrays.next());
        status = array_of<impact::status>(n, aligned<impact::status>(arrays.next()));
        for (auto* vectors : {&v_M0, &v_m0})  // read by the untimed reset only
            for (auto& v : *vectors)
                v = array_of<double>(n, arrays.next());
        std::mt19937_64 random(2026);
        std::uniform_real_distribution<double> unit(0.0, 1.0), coordinate(-10.0, 10.0);
        for (std::size_t i = 0; i < n; ++i) {
            M[i] = 0.1 + 10 * unit(random);
            m[i] = 0.1 + 10 * unit(random);
            eps[i] = unit(random);
            double closing = 0;
            for (std::size_t d = 0; d < D; ++d) {
                C_M[d][i] = coordinate(random);
                C_m[d][i] = coordinate(random);
                v_M[d][i] = coordinate(random);
                v_m[d][i] = coordinate(random);
                closing += (v_M[d][i] - v_m[d][i]) * (C_M[d][i] - C_m[d][i]);
            }
            if (closing > 0)  // every pair approaches: each one is a real collision
                for (std::size_t d = 0; d < D; ++d) {
                    v_M[d][i] = -v_M[d][i];
                    v_m[d][i] = -v_m[d][i];
                }
        }
        for (std::size_t d = 0; d < D; ++d) {
            std::copy(v_M[d].begin(), v_M[d].end(), v_M0[d].begin());
            std::copy(v_m[d].begin(), v_m[d].end(), v_m0[d].begin());
        }
    }

    // Copied, not assigned: an assignment would move v_M onto v_M0's allocator, i.e. its place.
    void reset()
    {
        for (std::size_t d = 0; d < D; ++d) {
            std::copy(v_M0[d].begin(), v_M0[d].end(), v_M[d].begin());
            std::copy(v_m0[d].begin(), v_m0[d].end(), v_m[d].begin());
        }
    }

    impact::collide_batch_data<double, D> data()
    {
        impact::collide_batch_data<double, D> d{};
        d.count = count;
        d.M = M.data();
        d.m = m.data();
        d.eps = eps.data();
        d.status = status.data();
        for (std::size_t k = 0; k < D; ++k) {
            d.C_M[k] = C_M[k].data();
            d.C_m[k] = C_m[k].data();
            d.v_M[k] = v_M[k].data();
            d.v_m[k] = v_m[k].data();
        }
        return d;
    }

    // Bytes a collision moves: every input read once, the velocities and status written.
    static constexpr double bytes_per_pair = (3 + 4 * D) * sizeof(double) + 2 * D * sizeof(double) + sizeof(impact::status);
};

// The memory-bandwidth probe's arrays: a = b + s c, laid out as a batch's arrays are.
struct triad_arrays {
    array_of<double> a, b, c;
    triad_arrays(std::size_t n, bool huge, layout how)
    {
        arrays_laid_out arrays(huge, how);
        a = array_of<double>(n, 0.0, arrays.next());
        b = array_of<double>(n, 1.0, arrays.next());
        c = array_of<double>(n, 2.0, arrays.next());
    }
    void run()
    {
        double* __restrict out = a.data();
        const double* __restrict x = b.data();
        const double* __restrict y = c.data();
        for (std::size_t i = 0, n = a.size(); i < n; ++i)
            out[i] = x[i] + 3.0 * y[i];
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
    static constexpr double bytes_per_element = 3 * sizeof(double);
};

// ---- The hand-written loop: the same arithmetic, written by hand -----------------

struct dd {
    double hi, lo;
};

// Double-double as Impact's compensated arithmetic does it: TwoSum and TwoProduct
// (through fma), a sum renormalised (it may cancel), a product not.
inline dd two_sum(double a, double b)
{
    const double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

inline dd add(dd a, dd b)
{
    const dd s = two_sum(a.hi, b.hi);
    const double e = s.lo + (a.lo + b.lo), h = s.hi + e;
    return {h, e - (h - s.hi)};
}

inline dd mul(dd a, dd b)
{
    const double p = a.hi * b.hi;
    return {p, std::fma(a.lo, b.hi, std::fma(a.hi, b.lo, std::fma(a.hi, b.hi, -p)))};
}

// a / b rounded to a double: q1 corrected by the remainder, exact through fma.
inline double div(dd a, dd b)
{
    const double q1 = a.hi / b.hi;
    const double r = std::fma(-q1, b.lo, std::fma(-q1, b.hi, a.hi) + a.lo);
    return q1 + r / b.hi;
}

// Written as one would by hand for speed: no branches (each status decided by masks, the
// denominator of a pair not resolved replaced by 1), arrays that do not overlap, so that
// the compiler vectorises the loop as it does the generated one. Held to the same contract
// as the generated loop, underflow included (like with like): a pair whose inputs are not
// all 0 or within [2^-k, 2^k] (k the generated header's, detail::collide_batch_<D>d_k) is
// left to the scalar kernel after its block of 8, which decides exactly.
// The form: `accurate`, k in double-double, as the accurate form computes it; `fast`, in plain
// double as the plain loop and the fast form do (k = (1 + eps) closing / ((M + m) rr), one
// division), the same guards, statuses and range test around it: the fast form's contract
// written by hand, to tell what the contract costs beside the plain loop; `guards`, the fast
// one without the range test and the scalar kernel after it (a pair whose values underflow
// keeps what the arithmetic gave): less than the contract, a floor under its cost.
enum class form { accurate, fast, guards };
template <std::size_t D, form f>
[[gnu::noinline]] void hand_written(pairs<D>& p)
{
    const double* __restrict M = p.M.data();
    const double* __restrict m = p.m.data();
    const double* __restrict eps = p.eps.data();
    std::array<const double*, D> C_M, C_m;
    std::array<double*, D> v_M, v_m;
    for (std::size_t d = 0; d < D; ++d) {
        C_M[d] = p.C_M[d].data();
        C_m[d] = p.C_m[d].data();
        v_M[d] = p.v_M[d].data();
        v_m[d] = p.v_m[d].data();
    }
    impact::status* __restrict status = p.status.data();
    // Blocks of 8 pairs, every array asked for 64 pairs ahead, as the generated batch does.
    constexpr std::size_t block = 8, ahead = 64;
    constexpr bool compensated = f == form::accurate;
    constexpr int k = compensated ? (D == 2 ? impact::detail::collide_batch_2d_k<double> : impact::detail::collide_batch_3d_k<double>)
                                  : (D == 2 ? impact::detail::collide_batch_2d_fast_k<double> : impact::detail::collide_batch_3d_fast_k<double>);
    constexpr double lowest = impact::detail::power_of_2<double>(-k), highest = impact::detail::power_of_2<double>(k);
    const auto pairs_from = [&](std::size_t first, std::size_t n) __attribute__((always_inline)) {
    IMPACT_INDEPENDENT_ITERATIONS
    for (std::size_t i = first; i < first + n; ++i) {
        // x * 0 is 0 for a finite x and NaN otherwise: one sum tests every value.
        double zero = 0;
        std::array<double, D> r;
        double rr = 0, closing = 0;
        for (std::size_t d = 0; d < D; ++d) {
            zero = std::fma(C_M[d][i], 0.0, std::fma(C_m[d][i], 0.0, zero));
            zero = std::fma(v_M[d][i], 0.0, std::fma(v_m[d][i], 0.0, zero));
            r[d] = C_M[d][i] - C_m[d][i];
            rr += r[d] * r[d];
            closing += r[d] * (v_M[d][i] - v_m[d][i]);
        }
        // Each condition a 64-bit integer, as wide as the doubles, combined with & (with bool
        // and &&, GCC vectorised neither the fast form's loop nor, in 3D, the accurate one's).
        const std::int64_t finite = zero == 0;
        std::int64_t bad_mass = !(M[i] > 0);
        bad_mass |= !(m[i] > 0);
        bad_mass |= !(std::fma(M[i], 0.0, m[i] * 0.0) == 0);
        std::int64_t bad_eps = !(eps[i] >= 0);
        bad_eps |= !(eps[i] <= 1);
        // Each choice by the bits, as the generated loop makes it (impact::detail::blend: with
        // ?:, GCC made branches of it it could not vectorise).
        using impact::detail::blend;
        impact::status s = blend(closing < 0, impact::status::ok, impact::status::separating);
        s = blend(rr > 0, s, impact::status::coincident_centres);
        s = blend(finite, s, impact::status::non_finite);
        s = blend(bad_eps, impact::status::invalid_restitution, s);
        s = blend(bad_mass, impact::status::invalid_mass, s);
        const std::int64_t ok = s == impact::status::ok;

        // k = (1 + eps) (dv . r) / ((M + m) r . r), in double-double (or plain double), then
        // the updates.
        std::int64_t usable;
        double k;
        if constexpr (compensated) {
            const dd r0 = two_sum(C_M[0][i], -C_m[0][i]);
            dd dot = mul(r0, two_sum(v_M[0][i], -v_m[0][i])), r2 = mul(r0, r0);
            for (std::size_t d = 1; d < D; ++d) {
                const dd rd = two_sum(C_M[d][i], -C_m[d][i]);
                dot = add(dot, mul(rd, two_sum(v_M[d][i], -v_m[d][i])));
                r2 = add(r2, mul(rd, rd));
            }
            // Refused out of range, as the kernels are: a divisor too small (or infinite) to
            // divide by in compensated arithmetic, or a result not finite.
            dd denominator = mul(two_sum(M[i], m[i]), r2);
            usable = ok & std::isgreaterequal(std::fabs(denominator.hi), std::numeric_limits<double>::min() / 0x1p-52) &
                     std::islessequal(std::fabs(denominator.hi), std::numeric_limits<double>::max());
            denominator.hi = blend(usable, denominator.hi, 1.0);
            k = div(mul(two_sum(1, eps[i]), dot), denominator);
        } else {
            // Refused out of range as the fast kernels are: a divisor 0 or not finite.
            double denominator = (M[i] + m[i]) * rr;
            // (quiet comparisons: one that may trap keeps GCC from vectorising the loop)
            usable = ok & (denominator != 0) & std::islessequal(std::fabs(denominator), std::numeric_limits<double>::max());
            denominator = blend(usable, denominator, 1.0);
            k = (1 + eps[i]) * closing / denominator;
        }
        std::array<double, D> after_M, after_m;
        double results = 0;
        for (std::size_t d = 0; d < D; ++d) {
            after_M[d] = v_M[d][i] - k * m[i] * r[d];
            after_m[d] = v_m[d][i] + k * M[i] * r[d];
            results = std::fma(after_M[d], 0.0, std::fma(after_m[d], 0.0, results));
        }
        // The inputs' range: the least magnitude not 0, and the largest; tested after the
        // arithmetic, as the generated loop tests it (tested first, it keeps the inputs live).
        // (An input 0 is admitted through impact::detail::magnitude_or, as in the generated
        // loop: with a comparison and a blend per input, it runs at half the speed.)
        const auto least = [](double a, double b) { return a < b ? a : b; };
        const auto most = [](double a, double b) { return a < b ? b : a; };
        double low = least(M[i], m[i]), high = most(M[i], m[i]);
        low = least(low, impact::detail::magnitude_or(eps[i], lowest));
        high = most(high, eps[i]);
        // Each axis written out (a loop over the axes left GCC's 3D loop unvectorised).
        const auto axis = [&](std::size_t d) __attribute__((always_inline)) {
            low = least(least(low, impact::detail::magnitude_or(C_M[d][i], lowest)), impact::detail::magnitude_or(C_m[d][i], lowest));
            low = least(least(low, impact::detail::magnitude_or(v_M[d][i], lowest)), impact::detail::magnitude_or(v_m[d][i], lowest));
            high = most(most(high, std::fabs(C_M[d][i])), std::fabs(C_m[d][i]));
            high = most(most(high, std::fabs(v_M[d][i])), std::fabs(v_m[d][i]));
        };
        axis(0);
        axis(1);
        if constexpr (D == 3)
            axis(2);
        const std::int64_t in_range = f == form::guards || (std::isgreaterequal(low, lowest) & std::islessequal(high, highest));
        const std::int64_t written = usable & (results == 0) & in_range;
        for (std::size_t d = 0; d < D; ++d) {
            v_M[d][i] = blend(written, after_M[d], v_M[d][i]);
            v_m[d][i] = blend(written, after_m[d], v_m[d][i]);
        }
        status[i] = blend(ok & !written, blend(usable & (results == 0), impact::status::underflow, impact::status::out_of_range), s);
    }
    };
    // The pairs left to the scalar kernel.
    const auto settle = [&](std::size_t first, std::size_t n) {
        bool any = false;
        for (std::size_t i = first; i < first + n; ++i)
            any |= status[i] == impact::status::underflow;
        if (!any)
            return;
        for (std::size_t i = first; i < first + n; ++i) {
            if (status[i] != impact::status::underflow)
                continue;
            std::array<double, D> cM, cm, vM, vm;
            for (std::size_t d = 0; d < D; ++d) {
                cM[d] = C_M[d][i];
                cm[d] = C_m[d][i];
                vM[d] = v_M[d][i];
                vm[d] = v_m[d][i];
            }
            const auto r = compensated ? impact::collide(M[i], m[i], cM, cm, vM, vm, eps[i])
                                       : impact::collide(M[i], m[i], cM, cm, vM, vm, eps[i], impact::fast);
            for (std::size_t d = 0; d < D; ++d) {
                v_M[d][i] = r.v_M[d];
                v_m[d][i] = r.v_m[d];
            }
            status[i] = r.status;
        }
    };
    std::size_t b = 0;
    for (; b + block <= p.count; b += block) {
        if (b + ahead < p.count) {
            for (const double* a : {M, m, eps})
                __builtin_prefetch(a + b + ahead, 0);
            for (std::size_t d = 0; d < D; ++d) {
                __builtin_prefetch(C_M[d] + b + ahead, 0);
                __builtin_prefetch(C_m[d] + b + ahead, 0);
                __builtin_prefetch(v_M[d] + b + ahead, 1);
                __builtin_prefetch(v_m[d] + b + ahead, 1);
            }
            __builtin_prefetch(status + b + ahead, 1);
        }
        pairs_from(b, block);
        if constexpr (f != form::guards)
            settle(b, block);
    }
    pairs_from(b, p.count - b);
    if constexpr (f != form::guards)
        settle(b, p.count - b);
}

// ---- Benchmarks -------------------------------------------------------------------

// Data shared by the repetitions of a benchmark, made once (4 million pairs take a while).
template <class Data>
Data& shared(std::size_t n, bool huge, layout how)
{
    static std::map<std::tuple<std::size_t, bool, layout>, Data> all;
    auto found = all.find({n, huge, how});
    if (found == all.end())
        found = all.emplace(std::piecewise_construct, std::forward_as_tuple(n, huge, how),
                            std::forward_as_tuple(n, huge, how))
                    .first;
    return found->second;
}

// Reads twice as many bytes as the largest caches hold (32 MiB here), so that nothing
// written before is still in them.
void flush_caches()
{
    static const array_of<double> sweep(std::size_t{8} << 20, 1.0);
    double sum = 0;
    for (std::size_t i = 0; i < sweep.size(); i += 8)
        sum += sweep[i];
    benchmark::DoNotOptimize(sum);
}

// Each loop a function of its own, none inlined into the harness: the compiler allocates
// registers for each alone, as it would in a program calling it.
template <std::size_t D>
[[gnu::noinline]] void generated_batch(pairs<D>& p)
{
    impact::collide_batch(p.data());
    benchmark::ClobberMemory();
}

// The batch loop before the underflow test: what the test costs, timed beside it.
template <std::size_t D>
[[gnu::noinline]] void generated_batch_before_underflow(pairs<D>& p)
{
    impact::before_underflow::collide_batch(p.data());
    benchmark::ClobberMemory();
}

// The fast form: the same guards and statuses, each velocity in its cheapest form within 16 ulps.
template <std::size_t D>
[[gnu::noinline]] void generated_fast_batch(pairs<D>& p)
{
    impact::collide_batch(p.data(), impact::fast);
    benchmark::ClobberMemory();
}

// The loop a simulation developer writes instead, with nothing of the kernels' contract:
// the update of Eq. 9 in vector form, k = (1 + eps) (v_M - v_m).r / ((M + m) |r|^2) and
// v_M - k m r, v_m + k M r, one division, no guards (every pair taken as approaching and
// valid), no compensated arithmetic, no status. Iterations declared independent, the
// arrays not overlapping, so that the compiler vectorises it.
template <std::size_t D>
[[gnu::noinline]] void plain_hand_written(pairs<D>& p)
{
    const double* __restrict M = p.M.data();
    const double* __restrict m = p.m.data();
    const double* __restrict eps = p.eps.data();
    std::array<const double*, D> C_M, C_m;
    std::array<double*, D> v_M, v_m;
    for (std::size_t d = 0; d < D; ++d) {
        C_M[d] = p.C_M[d].data();
        C_m[d] = p.C_m[d].data();
        v_M[d] = p.v_M[d].data();
        v_m[d] = p.v_m[d].data();
    }
    IMPACT_INDEPENDENT_ITERATIONS
    for (std::size_t i = 0; i < p.count; ++i) {
        std::array<double, D> r;
        double rr = 0, closing = 0;
        for (std::size_t d = 0; d < D; ++d) {
            r[d] = C_M[d][i] - C_m[d][i];
            rr += r[d] * r[d];
            closing += r[d] * (v_M[d][i] - v_m[d][i]);
        }
        const double k = (1 + eps[i]) * closing / ((M[i] + m[i]) * rr);
        for (std::size_t d = 0; d < D; ++d) {
            v_M[d][i] -= k * m[i] * r[d];
            v_m[d][i] += k * M[i] * r[d];
        }
    }
    benchmark::ClobberMemory();
}

template <std::size_t D>
[[gnu::noinline]] void generated_scalar(pairs<D>& p)
{
    for (std::size_t i = 0; i < p.count; ++i) {
        std::array<double, D> C_M, C_m, v_M, v_m;
        for (std::size_t d = 0; d < D; ++d) {
            C_M[d] = p.C_M[d][i];
            C_m[d] = p.C_m[d][i];
            v_M[d] = p.v_M[d][i];
            v_m[d] = p.v_m[d][i];
        }
        const auto r = impact::collide(p.M[i], p.m[i], C_M, C_m, v_M, v_m, p.eps[i]);
        for (std::size_t d = 0; d < D; ++d) {
            p.v_M[d][i] = r.v_M[d];
            p.v_m[d][i] = r.v_m[d];
        }
        p.status[i] = r.status;
    }
    benchmark::ClobberMemory();
}

// The loops timed side by side, and the figures each benchmark reports (medians of its
// repetitions): pairs per second (millions) of the three collision loops, the triad's bytes
// per second (GB), and the two ratios the batch kernel is held to.
enum loop { scalar_loop, batch_loop, hand_written_loop, before_loop, fast_loop, plain_loop, fast_hand_written_loop, guards_loop, triad_loop, loops };
const char* const pairs_per_second[] = {"scalar_M/s", "batch_M/s", "hand_M/s", "before_M/s", "fast_M/s", "plain_M/s", "fast_hand_M/s", "guards_M/s"};
const char* const triad_bandwidth = "triad_GB/s";
const char* const batch_per_hand_written = "batch/hand";
const char* const fast_per_plain = "fast/plain";
const char* const fast_hand_per_plain = "fast_hand/plain";
const char* const fast_per_fast_hand = "fast/fast_hand";
const char* const guards_per_plain = "guards/plain";
const char* const batch_per_plain = "batch/plain";
const char* const batch_per_triad = "batch/triad";
const char* const batch_per_before = "batch/before";

// Arguments: pairs (the triad runs over 5 times as many elements, about as many bytes as 2D
// pairs carry), page size in KiB, layout.
template <std::size_t D>
void side_by_side(benchmark::State& state)
{
    const std::size_t n = static_cast<std::size_t>(state.range(0));
    const bool huge = static_cast<std::size_t>(state.range(1)) == huge_pages;
    const layout how = static_cast<layout>(state.range(2));
    pairs<D>& p = shared<pairs<D>>(n, huge, how);
    triad_arrays& probe = shared<triad_arrays>(5 * n, huge, how);
    std::array<double, loops> seconds{};
    std::size_t first = 0;
    for (auto _ : state) {
        double pass = 0;
        for (std::size_t j = 0; j < loops; ++j) {
            const loop which = static_cast<loop>((first + j) % loops);
            p.reset();
            if (n > in_cache)
                flush_caches();
            const auto start = std::chrono::steady_clock::now();
            switch (which) {
            case scalar_loop: generated_scalar(p); break;
            case batch_loop: generated_batch(p); break;
            case hand_written_loop: hand_written<D, form::accurate>(p); break;
            case fast_hand_written_loop: hand_written<D, form::fast>(p); break;
            case guards_loop: hand_written<D, form::guards>(p); break;
            case before_loop: generated_batch_before_underflow(p); break;
            case fast_loop: generated_fast_batch(p); break;
            case plain_loop: plain_hand_written(p); break;
            default: probe.run(); break;
            }
            const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            seconds[which] += elapsed;
            pass += elapsed;
        }
        first = (first + 1) % loops;  // each loop in turn runs first, after the flush of another's data
        state.SetIterationTime(pass);
    }
    const double passes = static_cast<double>(state.iterations());
    for (loop which : {scalar_loop, batch_loop, hand_written_loop, before_loop, fast_loop, plain_loop, fast_hand_written_loop, guards_loop})
        state.counters[pairs_per_second[which]] = passes * n / seconds[which] / 1e6;
    state.counters[fast_per_plain] = seconds[plain_loop] / seconds[fast_loop];
    state.counters[fast_hand_per_plain] = seconds[plain_loop] / seconds[fast_hand_written_loop];
    state.counters[fast_per_fast_hand] = seconds[fast_hand_written_loop] / seconds[fast_loop];
    state.counters[guards_per_plain] = seconds[plain_loop] / seconds[guards_loop];
    state.counters[batch_per_plain] = seconds[plain_loop] / seconds[batch_loop];
    const double triad_bytes = passes * probe.a.size() * triad_arrays::bytes_per_element / seconds[triad_loop];
    state.counters[triad_bandwidth] = triad_bytes / 1e9;
    state.counters[batch_per_hand_written] = seconds[hand_written_loop] / seconds[batch_loop];
    state.counters[batch_per_before] = seconds[before_loop] / seconds[batch_loop];
    state.counters[batch_per_triad] = passes * n * pairs<D>::bytes_per_pair / seconds[batch_loop] / triad_bytes;
}

// Collects the medians of the repetitions, to print the figures together at the end.
class ratio_reporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override
    {
        for (const Run& run : runs)
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
                for (const auto& [name, counter] : run.counters)
                    medians[run.run_name.function_name + "/" + run.run_name.args][name] = counter.value;
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, std::map<std::string, double>> medians;  // by benchmark and argument
};

// The regimes every benchmark runs in: pairs, page size in KiB, layout.
struct regime {
    std::size_t pairs, page_KiB;
    layout how;
};
constexpr regime regimes[] = {{in_cache, small_pages, staggered},
                              {out_of_cache, small_pages, same_offset},
                              {out_of_cache, small_pages, staggered},
                              {out_of_cache, huge_pages, staggered}};

void in_every_regime(benchmark::internal::Benchmark* b)
{
    b->ArgNames({"pairs", "page_KiB", "staggered"});
    for (const regime& r : regimes)
        b->Args({static_cast<std::int64_t>(r.pairs), static_cast<std::int64_t>(r.page_KiB), r.how});
}

// Repetitions of each benchmark, whose medians are reported.
constexpr int repetitions = 7;

} // namespace

#define IMPACT_SIDE_BY_SIDE(D)                                                                               \
    BENCHMARK(side_by_side<D>)                                                                              \
        ->Apply(in_every_regime)                                                                            \
        ->UseManualTime()                                                                                   \
        ->Repetitions(repetitions)                                                                          \
        ->ReportAggregatesOnly(true)                                                                        \
        ->Unit(benchmark::kMillisecond)

IMPACT_SIDE_BY_SIDE(2);
IMPACT_SIDE_BY_SIDE(3);

namespace {

// How much of this process's memory is on 2 MiB pages, in MiB (Linux; -1 if unknown):
// MADV_HUGEPAGE is advice, which the system may decline.
long huge_pages_granted()
{
    std::FILE* f = std::fopen("/proc/self/smaps_rollup", "r");
    if (!f)
        return -1;
    long kib = -1;
    char line[256];
    while (std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "AnonHugePages: %ld kB", &kib) == 1)
            break;
    std::fclose(f);
    return kib < 0 ? -1 : kib / 1024;
}

} // namespace

int main(int argc, char** argv)
{
    // The repetitions of all benchmarks interleaved in random order, so that a change in the
    // machine's load falls on every regime alike.
    std::vector<char*> arguments{argv[0], const_cast<char*>("--benchmark_enable_random_interleaving=true")};
    arguments.insert(arguments.end(), argv + 1, argv + argc);  // the caller's flags come later and win
    int count = static_cast<int>(arguments.size());
    benchmark::Initialize(&count, arguments.data());
    ratio_reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    std::printf("\nMedians of %d repetitions; targets: batch / hand-written >= 0.95, and out of cache the batch's "
                "bytes/s >= 80%% of the triad's. batch/before: the batch loop against the same loop before its "
                "underflow test.\nThe fast form (impact::fast) against the plain loop (no guards, no compensation): "
                "fast/plain >= 0.9 in and out of cache; the accurate batch: batch/plain >= 0.6 out of cache.\n"
                "Compiled for %s.\n",
                repetitions, impact::benchmarks::isa().c_str());
    std::printf("%-3s %-12s %-9s %-12s %9s %9s %9s %10s %10s %11s %10s %12s\n", "", "pairs", "pages", "layout",
                "scalar M/s", "batch M/s", "hand M/s", "triad GB/s", "batch/hand", "batch/triad", "before M/s",
                "batch/before");
    for (int d : {2, 3})
        for (const auto& [pairs, pages, how] : regimes) {
            const std::string name = "side_by_side<" + std::to_string(d) + ">/pairs:" + std::to_string(pairs) +
                                     "/page_KiB:" + std::to_string(pages) + "/staggered:" + std::to_string(how);
            const auto found = reporter.medians.find(name);
            if (found == reporter.medians.end())
                continue;
            auto figure = [&](const char* counter) { return found->second[counter]; };
            std::printf("%-3s %-12zu %-9s %-12s %9.1f %9.1f %9.1f %10.2f %10.3f %10.0f%% %10.1f %12.3f\n",
                        (std::to_string(d) + "D").c_str(), pairs, pages == huge_pages ? "2 MiB" : "4 KiB",
                        how == staggered ? "staggered" : "same offset", figure(pairs_per_second[scalar_loop]),
                        figure(pairs_per_second[batch_loop]), figure(pairs_per_second[hand_written_loop]),
                        figure(triad_bandwidth), figure(batch_per_hand_written), 100 * figure(batch_per_triad),
                        figure(pairs_per_second[before_loop]), figure(batch_per_before));
        }
    std::printf("\nfast hand: the fast form's contract written by hand (hand_written<D, form::fast>); guards: the same "
                "without its range test and scalar kernel (form::guards), less than the contract: what the guards "
                "and statuses alone cost beside the plain loop.\n");
    std::printf("%-3s %-12s %-9s %-12s %9s %9s %9s %10s %11s %15s %14s %12s\n", "", "pairs", "pages", "layout", "fast M/s",
                "plain M/s", "batch M/s", "fast/plain", "batch/plain", "fast hand/plain", "fast/fast hand",
                "guards/plain");
    for (int d : {2, 3})
        for (const auto& [pairs, pages, how] : regimes) {
            const std::string name = "side_by_side<" + std::to_string(d) + ">/pairs:" + std::to_string(pairs) +
                                     "/page_KiB:" + std::to_string(pages) + "/staggered:" + std::to_string(how);
            const auto found = reporter.medians.find(name);
            if (found == reporter.medians.end())
                continue;
            auto figure = [&](const char* counter) { return found->second[counter]; };
            std::printf("%-3s %-12zu %-9s %-12s %9.1f %9.1f %9.1f %10.3f %11.3f %15.3f %14.3f %12.3f\n", (std::to_string(d) + "D").c_str(),
                        pairs, pages == huge_pages ? "2 MiB" : "4 KiB", how == staggered ? "staggered" : "same offset",
                        figure(pairs_per_second[fast_loop]), figure(pairs_per_second[plain_loop]),
                        figure(pairs_per_second[batch_loop]), figure(fast_per_plain), figure(batch_per_plain),
                        figure(fast_hand_per_plain), figure(fast_per_fast_hand), figure(guards_per_plain));
        }
    std::printf("arrays on 2 MiB pages at the end: %ld MiB of the %zu MiB asked for (the system may grant fewer; "
                "the 2 MiB-page figures hold for as many as it granted)\n",
                huge_pages_granted(), huge_bytes_asked >> 20);
    return 0;
}

// The part of impact/common.hpp written by hand, copied into it after its banner
// (src/emit/kernel_prelude.hpp in Impact's sources): the standard headers the kernels
// use, and the macros that let compilers vectorise, prefetch and inline them.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

// The arrays a batch kernel writes overlap no other array (`restrict`), and its
// iterations are independent: compilers may vectorise its loop.
#if defined(__GNUC__) || defined(__clang__) || defined(_MSC_VER)
#define IMPACT_RESTRICT __restrict
#else
#define IMPACT_RESTRICT
#endif
#if defined(__GNUC__) && !defined(__clang__)  // Clang needs no more than `restrict`
#define IMPACT_INDEPENDENT_ITERATIONS _Pragma("GCC ivdep")
#else
#define IMPACT_INDEPENDENT_ITERATIONS
#endif
// A loop over the 8 pairs of a block kept a loop, so that it is vectorised: GCC and Clang
// unroll a loop that short completely first where its body is small, and then vectorise none
// of it (collide_line's batch with GCC for AVX-512: 42 ms for 4 million pairs, 11.6 ms with
// its sure block's loops kept).
#if defined(__clang__)
#define IMPACT_KEEP_LOOP _Pragma("clang loop unroll(disable)")
#elif defined(__GNUC__)
#define IMPACT_KEEP_LOOP _Pragma("GCC unroll 1")
#else
#define IMPACT_KEEP_LOOP
#endif
// Asks for the cache line at p ahead of its use (for writing if `write`): a batch loop
// streams so many arrays at once that the processor's own prefetching falls behind.
#if defined(__GNUC__) || defined(__clang__)
#define IMPACT_PREFETCH(p, write) __builtin_prefetch((p), (write))
#else
#define IMPACT_PREFETCH(p, write) ((void)0)
#endif
// A function inlined wherever it is called, whatever the compiler's estimate of the cost.
#if defined(__GNUC__) || defined(__clang__)
#define IMPACT_ALWAYS_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define IMPACT_ALWAYS_INLINE __forceinline
#else
#define IMPACT_ALWAYS_INLINE inline
#endif

// The kernels' arithmetic as written, whatever the flags of the code that includes them:
// their guards test for NaN and infinities, and their compensated arithmetic (two-sum and
// two-product corrections such as `t - (a - b)`) is exactly what -ffast-math's
// reassociation simplifies away (built with -O3 -march=native -ffast-math and no pragma, NaN
// velocities went unnoticed and collide's velocities were 7.8 ulps off, against 3.9). Every
// generated header opens IMPACT_PRECISE_BEGIN before its code and closes it with
// IMPACT_PRECISE_END.
// GCC: its options for the functions defined in between, as if compiled without
// -ffast-math (-Ofast, -ffinite-math-only, -fassociative-math, -freciprocal-math ...) and
// without fusing products into sums (-ffp-contract=fast, GCC's default outside ISO modes).
// Clang: precise floating point in between. Clang disregards every pragma on contraction
// under -ffp-contract=fast (which its -ffast-math and -Ofast imply): products may then be
// fused into sums, and the batch loop's results differ from the scalar kernel's by an ulp or
// so; docs/kernels.md ("The flags users have") gives the errors measured so.
// Neither pragma changes the processor's modes: a program linked with -ffast-math (GCC and
// Clang link crtfastmath.o) flushes denormals to zero; docs/kernels.md ("The flags users
// have") says what the kernels do then.
#if defined(__clang__)
#define IMPACT_PRECISE_BEGIN _Pragma("float_control(precise, on, push)") _Pragma("clang fp contract(off)")
#define IMPACT_PRECISE_END _Pragma("float_control(pop)")
#elif defined(__GNUC__)
// -fno-fast-math also asks for errno and trapping maths: the caller's choice is kept for those
// (they change no result, and without them GCC vectorises more: the rough batch loop's square
// root, the AVX2 loops' divisions; docs/design-kernels.md ("The batch loop: one program, no
// branches") says what a discarded lane's division may then do).
#if defined(__NO_MATH_ERRNO__)
#define IMPACT_KEEP_NO_MATH_ERRNO _Pragma("GCC optimize(\"no-math-errno\")")
#else
#define IMPACT_KEEP_NO_MATH_ERRNO
#endif
#if defined(__NO_TRAPPING_MATH__)
#define IMPACT_KEEP_NO_TRAPPING_MATH _Pragma("GCC optimize(\"no-trapping-math\")")
#else
#define IMPACT_KEEP_NO_TRAPPING_MATH
#endif
// And no vectorisation of straight-line code (-fno-tree-slp-vectorize; loops still vectorise):
// GCC 12 at -O3 on a processor with FMA fuses a product into an alternating subtract and add
// of two lanes (vfmaddsub), -ffp-contract=off or not, and the scalar kernel's results then
// differed from the batch's by an ulp or two (the 2D rough kernel, 78 of 4000 collisions).
#define IMPACT_PRECISE_BEGIN                                                                   \
    _Pragma("GCC push_options")                                                                \
        _Pragma("GCC optimize(\"no-fast-math\", \"fp-contract=off\", \"no-tree-slp-vectorize\")") \
            IMPACT_KEEP_NO_MATH_ERRNO IMPACT_KEEP_NO_TRAPPING_MATH
#define IMPACT_PRECISE_END _Pragma("GCC pop_options")
#else
#define IMPACT_PRECISE_BEGIN
#define IMPACT_PRECISE_END
#endif

IMPACT_PRECISE_BEGIN  // closed at the end of impact/common.hpp

namespace impact {

/// The tag that asks for a kernel's fast form: `impact::collide(..., impact::fast)`,
/// `impact::collide_batch(data, impact::fast)`, and alike for every kernel. The fast form
/// has the accurate form's guards and statuses; each output is computed in its cheapest
/// candidate form within its fast bound (16 ulps of its scale unless its derivation file
/// sets another), measured and reported in verification.md beside the accurate form.
struct fast_t {
    explicit constexpr fast_t() = default;
};
inline constexpr fast_t fast{};

} // namespace impact

namespace impact::detail {

/// Whether x is finite, read from its bits: an infinity or a NaN is a value whose exponent
/// bits are all ones. Under -ffinite-math-only (and so -ffast-math and -Ofast) a compiler
/// may take every value as finite and make std::isfinite true, even between
/// IMPACT_PRECISE_BEGIN and IMPACT_PRECISE_END (GCC folds it in <cmath>, compiled with the
/// caller's flags); no flag folds an integer test. Float, double, x87's and IEEE's quadruple
/// long double (on a little-endian machine) so; any other format through std::isfinite.
template <class Real>
IMPACT_ALWAYS_INLINE bool finite(Real x) noexcept
{
    using limits = std::numeric_limits<Real>;
    constexpr bool binary = limits::radix == 2;
    if constexpr (binary && sizeof(Real) == 4 && limits::digits == 24 && limits::max_exponent == 128) {
        std::uint32_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return (bits & 0x7f800000u) != 0x7f800000u;
    } else if constexpr (binary && sizeof(Real) == 8 && limits::digits == 53 && limits::max_exponent == 1024) {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return (bits & 0x7ff0000000000000u) != 0x7ff0000000000000u;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    } else if constexpr (binary && limits::max_exponent == 16384 && (limits::digits == 64 || limits::digits == 113) &&
                         sizeof(Real) >= 10) {
        // The sign and the 15 exponent bits: bytes 8 and 9 of x87's 80 bits, 14 and 15 of 128.
        unsigned char bytes[sizeof(Real)];
        std::memcpy(bytes, &x, sizeof bytes);
        constexpr std::size_t high = limits::digits == 64 ? 9 : 15;
        return ((bytes[high] & 0x7fu) << 8 | bytes[high - 1]) != 0x7fffu;
#endif
    } else {
        return std::isfinite(x);
    }
}

/// Whether a comparison with NaN is false in the kernels' code, as IEEE 754 has it, so that
/// a sure block's range test (a sum of squares) also refuses NaN: not where the code that
/// includes the kernels is compiled with -ffinite-math-only (-ffast-math, -Ofast). Clang then
/// takes NaN as absent from the whole program; GCC, despite IMPACT_PRECISE_BEGIN, let a NaN
/// input through the sure block of collide_batch (test_kernels_hostile_fast_math). There, the
/// sure block tests its inputs' finiteness too (zero_if_finite, below).
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
inline constexpr bool nan_compares_false = false;
#else
inline constexpr bool nan_compares_false = true;
#endif

/// 1 where a and b both hold (where any of b holds), as integers: the `&` (`|`) of a batch
/// loop's conditions, without the branch `&&` (`||`) may be made into, and which Clang's
/// -Wbitwise-instead-of-logical does not mistake for a `&&` (`||`) mistyped.
IMPACT_ALWAYS_INLINE int both(bool a, bool b) noexcept
{
    return int(a) & int(b);
}
template <class... B>
IMPACT_ALWAYS_INLINE int either(B... b) noexcept
{
    return (int(b) | ...);
}

/// 0 where x (and y) are finite, and not 0 elsewhere: a batch loop sums these, one sum
/// for many values, and tests the sum against 0. x * 0 is 0 for a finite x and NaN
/// otherwise (fused, one operation a value). But Clang under -ffinite-math-only (so
/// -ffast-math, -Ofast) folds x * 0 to 0 and compares a NaN as equal to 0 even in precise
/// code (its code generator takes NaN as absent for the whole program): there, 0 or 1 from
/// the bits. GCC compiles the product as written between IMPACT_PRECISE_BEGIN and _END.
#if defined(__clang__) && defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
template <class Real>
IMPACT_ALWAYS_INLINE Real zero_if_finite(Real x) noexcept
{
    return finite(x) ? Real(0) : Real(1);
}
template <class Real>
IMPACT_ALWAYS_INLINE Real zero_if_finite(Real x, Real y) noexcept
{
    return both(finite(x), finite(y)) ? Real(0) : Real(1);
}
#else
template <class Real>
IMPACT_ALWAYS_INLINE Real zero_if_finite(Real x) noexcept
{
    return x * Real(0);
}
template <class Real>
IMPACT_ALWAYS_INLINE Real zero_if_finite(Real x, Real y) noexcept
{
    return std::fma(x, Real(0), y * Real(0));
}
#endif

/// a >= b and a <= b, false where either is NaN, raising no flag: std::isgreaterequal and
/// std::islessequal, but written here. GCC inlines no function of <cmath>, compiled with the
/// caller's flags, into a kernel compiled with other floating-point options, and a batch loop
/// that calls a function is not vectorised.
template <class Real>
IMPACT_ALWAYS_INLINE bool at_least(Real a, Real b) noexcept
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_isgreaterequal(a, b);
#else
    return std::isgreaterequal(a, b);
#endif
}
template <class Real>
IMPACT_ALWAYS_INLINE bool at_most(Real a, Real b) noexcept
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_islessequal(a, b);
#else
    return std::islessequal(a, b);
#endif
}

/// x where `chosen` is not 0, otherwise `other`, by the bits of both (a batch loop's
/// choices). Without a branch for a compiler to make of it: GCC made `d / (c ? x : 1)`
/// a division only where c held, and `s = c ? status : s` branches it followed from
/// guard to guard, selecting booleans it could not vectorise without AVX-512 (or,
/// for the division, -fno-trapping-math). An int64 condition is one mask as wide as
/// a double per lane.
template <class T>
IMPACT_ALWAYS_INLINE T blend(std::int64_t chosen, T x, T other) noexcept
{
    if constexpr (sizeof(T) == sizeof(std::uint64_t) || sizeof(T) == sizeof(std::uint32_t)) {
        using bits = std::conditional_t<sizeof(T) == sizeof(std::uint64_t), std::uint64_t, std::uint32_t>;
        bits a, b;
        std::memcpy(&a, &x, sizeof a);
        std::memcpy(&b, &other, sizeof b);
        // The mask in a statement of its own: in one expression, GCC folds `& -mask`
        // to a select of booleans again.
        const bits mask = bits(0) - static_cast<bits>(chosen != 0);
        const bits r = b ^ ((a ^ b) & mask);
        T out;
        std::memcpy(&out, &r, sizeof out);
        return out;
    } else {
        return chosen != 0 ? x : other;
    }
}

} // namespace impact::detail

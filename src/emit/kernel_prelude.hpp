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

// Speed of the generated collision kernels, side by side in one run with a hand-written
// batch loop of the same arithmetic and a memory-bandwidth probe (a triad).
//
// A benchmark, never a test: it reports collisions per second in cache (4 096 pairs)
// and out of cache (4 194 304 pairs), and at the end the ratios the kernels are held
// to: batch / hand-written, and bytes per second of the batch out of cache / triad.
// Every pass starts from the same approaching pairs (velocities are reset, untimed),
// since a resolved pair separates and would take the kernel's early exit next time.
// Out of cache, the reset's writes are then pushed out to memory, untimed too: left in
// the cache, they would be written back during the kernel's pass and counted against
// it, while the triad it is compared with has no such writes to carry.
// Out of cache, the batch loops and the triad run twice: on arrays of ordinary 4 KiB
// pages and on arrays of 2 MiB pages (madvise MADV_HUGEPAGE, as programs that stream
// large arrays allocate them). A 3D batch streams 16 arrays at once; on 4 KiB pages it
// crosses 16 pages every 512 pairs, and the misses of the address translation, not the
// memory's bandwidth, bound it.
#include "impact/impact.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <new>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <sys/mman.h>

namespace {

constexpr std::size_t in_cache = 4096;
constexpr std::size_t out_of_cache = 4194304;

// The size of the pages an array is on, in KiB (the benchmarks' second argument).
constexpr std::size_t small_pages = 4, huge_pages = 2048;

// Arrays aligned to 64 bytes, as data for SIMD loops are: std::vector's own 16-byte
// alignment splits every 512-bit load across two cache lines, which halves the bandwidth
// a loop over many arrays reaches. An array of `huge` pages is aligned to 2 MiB and asks
// the kernel for 2 MiB pages.
// Bytes held now by arrays that asked for 2 MiB pages.
std::size_t huge_bytes_asked = 0;

template <class T>
struct aligned {
    using value_type = T;
    static constexpr std::size_t line = 64, huge_page = std::size_t{2} << 20;
    bool huge = false;
    // An array assigned another takes its pages along.
    using propagate_on_container_copy_assignment = std::true_type;
    using propagate_on_container_move_assignment = std::true_type;
    using propagate_on_container_swap = std::true_type;
    aligned() = default;
    explicit aligned(bool on_huge_pages) noexcept : huge(on_huge_pages) {}
    template <class U>
    aligned(const aligned<U>& other) noexcept : huge(other.huge) {}
    std::size_t alignment() const { return huge ? huge_page : line; }
    T* allocate(std::size_t n)
    {
        const std::size_t bytes = (n * sizeof(T) + alignment() - 1) / alignment() * alignment();
        void* p = ::operator new(bytes, std::align_val_t{alignment()});
        if (huge) {
            madvise(p, bytes, MADV_HUGEPAGE);  // advice: the system may decline (see huge_pages_granted)
            huge_bytes_asked += bytes;
        }
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept
    {
        if (huge)
            huge_bytes_asked -= (n * sizeof(T) + alignment() - 1) / alignment() * alignment();
        ::operator delete(p, std::align_val_t{alignment()});
    }
    template <class U>
    bool operator==(const aligned<U>& other) const noexcept { return huge == other.huge; }
    template <class U>
    bool operator!=(const aligned<U>& other) const noexcept { return huge != other.huge; }
};
template <class T>
using array_of = std::vector<T, aligned<T>>;

template <std::size_t D>
struct pairs {
    std::size_t count = 0;
    array_of<double> M, m, eps;
    std::array<array_of<double>, D> C_M, C_m, v_M, v_m, v_M0, v_m0;
    array_of<impact::status> status;

    pairs(std::size_t n, bool huge)
        : count(n), M(n, aligned<double>(huge)), m(n, aligned<double>(huge)), eps(n, aligned<double>(huge)),
          status(n, aligned<impact::status>(huge))
    {
        std::mt19937_64 random(2026);
        std::uniform_real_distribution<double> unit(0.0, 1.0), coordinate(-10.0, 10.0);
        for (auto* vectors : {&C_M, &C_m, &v_M, &v_m, &v_M0, &v_m0})
            for (auto& v : *vectors)
                v = array_of<double>(n, aligned<double>(huge));
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
        v_M0 = v_M;
        v_m0 = v_m;
    }

    void reset()
    {
        v_M = v_M0;
        v_m = v_m0;
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
// the compiler vectorises the loop as it does the generated one.
template <std::size_t D>
void hand_written(pairs<D>& p)
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
        const bool finite = zero == 0;
        bool bad_mass = !(M[i] > 0);
        bad_mass |= !(m[i] > 0);
        bad_mass |= !(std::fma(M[i], 0.0, m[i] * 0.0) == 0);
        bool bad_eps = !(eps[i] >= 0);
        bad_eps |= !(eps[i] <= 1);
        impact::status s = closing < 0 ? impact::status::ok : impact::status::separating;
        s = rr > 0 ? s : impact::status::coincident_centres;
        s = finite ? s : impact::status::non_finite;
        s = bad_eps ? impact::status::invalid_restitution : s;
        s = bad_mass ? impact::status::invalid_mass : s;
        const bool ok = s == impact::status::ok;

        // k = (1 + eps) (dv . r) / ((M + m) r . r), in double-double, then the updates.
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
        const bool usable = ok && std::fabs(denominator.hi) >= std::numeric_limits<double>::min() / 0x1p-52 &&
                            std::fabs(denominator.hi) <= std::numeric_limits<double>::max();
        denominator.hi = usable ? denominator.hi : 1.0;
        const double k = div(mul(two_sum(1, eps[i]), dot), denominator);
        std::array<double, D> after_M, after_m;
        double results = 0;
        for (std::size_t d = 0; d < D; ++d) {
            after_M[d] = v_M[d][i] - k * m[i] * r[d];
            after_m[d] = v_m[d][i] + k * M[i] * r[d];
            results = std::fma(after_M[d], 0.0, std::fma(after_m[d], 0.0, results));
        }
        const bool written = usable && results == 0;
        for (std::size_t d = 0; d < D; ++d) {
            v_M[d][i] = written ? after_M[d] : v_M[d][i];
            v_m[d][i] = written ? after_m[d] : v_m[d][i];
        }
        status[i] = ok && !written ? impact::status::out_of_range : s;
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
    }
    pairs_from(b, p.count - b);
}

// ---- Benchmarks -------------------------------------------------------------------

template <std::size_t D>
pairs<D>& shared_pairs(std::size_t n, bool huge)
{
    static std::map<std::pair<std::size_t, bool>, pairs<D>> all;
    auto found = all.find({n, huge});
    if (found == all.end())
        found = all.emplace(std::make_pair(n, huge), pairs<D>(n, huge)).first;
    return found->second;
}

bool on_huge_pages(const benchmark::State& state)
{
    return static_cast<std::size_t>(state.range(1)) == huge_pages;
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

template <std::size_t D, class Body>
void run(benchmark::State& state, Body body)
{
    pairs<D>& p = shared_pairs<D>(static_cast<std::size_t>(state.range(0)), on_huge_pages(state));
    for (auto _ : state) {
        state.PauseTiming();
        p.reset();
        if (p.count > in_cache)
            flush_caches();
        state.ResumeTiming();
        body(p);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * p.count));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * p.count * pairs<D>::bytes_per_pair));
}

template <std::size_t D>
void generated_batch(benchmark::State& state)
{
    run<D>(state, [](pairs<D>& p) { impact::collide_batch(p.data()); });
}

template <std::size_t D>
void generated_scalar(benchmark::State& state)
{
    run<D>(state, [](pairs<D>& p) {
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
    });
}

template <std::size_t D>
void hand_written_batch(benchmark::State& state)
{
    run<D>(state, [](pairs<D>& p) { hand_written(p); });
}

// a = b + s c: the bandwidth a loop over this much memory can reach.
void triad(benchmark::State& state)
{
    const std::size_t n = static_cast<std::size_t>(state.range(0));
    const aligned<double> pages(on_huge_pages(state));
    array_of<double> a(n, pages), b(n, 1.0, pages), c(n, 2.0, pages);
    for (auto _ : state) {
        for (std::size_t i = 0; i < n; ++i)
            a[i] = b[i] + 3.0 * c[i];
        benchmark::DoNotOptimize(a.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * n * 3 * sizeof(double)));
}

// Collects results to print the ratios at the end.
class ratio_reporter : public benchmark::ConsoleReporter {
public:
    // The median of the repetitions of each benchmark.
    void ReportRuns(const std::vector<Run>& runs) override
    {
        for (const Run& run : runs) {
            if (run.run_type != Run::RT_Aggregate || run.aggregate_name != "median")
                continue;
            std::string name = run.run_name.str();  // e.g. triad/n:20480/page_KiB:4/repeats:7/real_time
            if (const auto at = name.find("/repeats:"); at != std::string::npos)
                name.erase(at, name.find('/', at + 1) - at);
            items[name] = run.counters.count("items_per_second") ? run.counters.at("items_per_second").value : 0;
            bytes[name] = run.counters.count("bytes_per_second") ? run.counters.at("bytes_per_second").value : 0;
        }
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, double> items, bytes;
};

} // namespace

// Each benchmark repeated, the repetitions of all interleaved in random order (see
// main), so that a change in the machine's load falls on every one alike; the ratios are
// taken between medians. Arguments: pairs (or triad elements), page size in KiB.
// The triad runs over 5 times as many elements: as many bytes as 2D pairs carry, roughly.
#define IMPACT_BENCHMARK(f, elements_per_pair)                                                                \
    BENCHMARK(f)                                                                                              \
        ->ArgNames({"n", "page_KiB"})                                                                        \
        ->Args({in_cache * elements_per_pair, small_pages})                                                   \
        ->Args({out_of_cache * elements_per_pair, small_pages})                                               \
        ->Args({out_of_cache * elements_per_pair, huge_pages})                                                \
        ->UseRealTime()                                                                                       \
        ->Repetitions(7)                                                                                      \
        ->ReportAggregatesOnly(true)                                                                          \
        ->Unit(benchmark::kMicrosecond)

IMPACT_BENCHMARK(generated_scalar<2>, 1);
IMPACT_BENCHMARK(generated_batch<2>, 1);
IMPACT_BENCHMARK(hand_written_batch<2>, 1);
IMPACT_BENCHMARK(generated_scalar<3>, 1);
IMPACT_BENCHMARK(generated_batch<3>, 1);
IMPACT_BENCHMARK(hand_written_batch<3>, 1);
IMPACT_BENCHMARK(triad, 5);

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
    std::vector<char*> arguments{argv[0], const_cast<char*>("--benchmark_enable_random_interleaving=true")};
    arguments.insert(arguments.end(), argv + 1, argv + argc);  // the caller's flags come later and win
    int count = static_cast<int>(arguments.size());
    benchmark::Initialize(&count, arguments.data());
    ratio_reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const auto key = [](const std::string& f, std::size_t n, std::size_t pages) {
        return f + "/n:" + std::to_string(n) + "/page_KiB:" + std::to_string(pages) + "/real_time";
    };
    const std::pair<std::size_t, std::size_t> regimes[] = {
        {in_cache, small_pages}, {out_of_cache, small_pages}, {out_of_cache, huge_pages}};
    for (int d : {2, 3}) {
        const std::string D = "<" + std::to_string(d) + ">";
        for (const auto& [n, pages] : regimes) {
            const double batch = reporter.items[key("generated_batch" + D, n, pages)];
            const double hand = reporter.items[key("hand_written_batch" + D, n, pages)];
            if (batch > 0 && hand > 0)
                std::printf("%dD, %zu pairs, %zu KiB pages: generated batch / hand-written = %.3f\n", d, n, pages,
                            batch / hand);
        }
        for (std::size_t pages : {small_pages, huge_pages}) {
            const double bytes = reporter.bytes[key("generated_batch" + D, out_of_cache, pages)];
            const double probe = reporter.bytes[key("triad", out_of_cache * 5, pages)];
            if (bytes > 0 && probe > 0)
                std::printf("%dD out of cache, %zu KiB pages: generated batch moves %.2f GB/s, the triad %.2f GB/s: "
                            "%.0f%%\n",
                            d, pages, bytes / 1e9, probe / 1e9, 100 * bytes / probe);
        }
    }
    std::printf("arrays on 2 MiB pages at the end: %ld MiB of the %zu MiB asked for (the system may grant fewer; "
                "the %zu KiB-page figures hold for as many as it granted)\n",
                huge_pages_granted(), huge_bytes_asked >> 20, huge_pages);
    return 0;
}

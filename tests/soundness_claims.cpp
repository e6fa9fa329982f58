// The grammar of soundness_claims.h.
#include "soundness_claims.h"

#include <functional>

namespace impact::soundness {

namespace {

using GiNaC::numeric;
using op = term::op;

class drawer {
public:
    drawer(std::mt19937_64& rng, std::vector<std::string> names) : rng_(rng), names_(std::move(names)) {}

    std::uint64_t below(std::uint64_t n) { return rng_() % n; }
    bool chance(int percent) { return static_cast<int>(below(100)) < percent; }

    term leaf()
    {
        if (chance(18)) {
            static const numeric constants[] = {1, 2, 3, numeric(1, 2), 5};
            return term::number(constants[below(5)]);
        }
        return term::symbol(names_[below(names_.size())]);
    }

    // A small expression: a rational function, a radical, abs, exp or log of what is below.
    term draw(int depth, bool under_exp = false)
    {
        if (depth <= 0 || chance(25))
            return leaf();
        const int pick = static_cast<int>(below(100));
        const auto next = [&] { return draw(depth - 1, under_exp); };
        if (pick < 18)
            return next() + next();
        if (pick < 30)
            return next() - next();
        if (pick < 46)
            return next() * next();
        if (pick < 52)
            return term::number(numeric(2 + static_cast<int>(below(3)))) * next();
        if (pick < 60)
            return next() / next();
        if (pick < 68)
            return pow(next(), 2);
        if (pick < 75)
            return call(op::sqrt, next());
        if (pick < 82)
            return call(op::abs, next());
        if (pick < 87 && !under_exp)
            return call(op::exp, draw(depth - 1, true));
        if (pick < 92)
            return call(op::log, next());
        if (pick < 96) {
            static const int exponents[][2] = {{1, 3}, {2, 3}, {-1, 2}, {3, 2}, {-1, 1}, {-2, 1}};
            const auto& e = exponents[below(6)];
            return pow(next(), e[0], e[1]);
        }
        return -next();
    }

    std::mt19937_64& rng_;
    std::vector<std::string> names_;
};

term num(int n, int d = 1) { return term::number(numeric(n, d)); }

struct family {
    const char* name;
    bool inequality;
    std::function<relation_claim(const term& a, const term& b, const term& c, drawer& draw)> make;
};

// Each is true wherever both its sides are defined.
const std::vector<family>& families()
{
    using r = relation;
    static const std::vector<family> all = {
        {"cancel", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{a * b / b, r::equal, a};
         }},
        {"square", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{pow(a + b, 2), r::equal, pow(a, 2) + num(2) * a * b + pow(b, 2)};
         }},
        {"difference_of_squares", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{(pow(a, 2) - pow(b, 2)) / (a - b), r::equal, a + b};
         }},
        {"root_of_square", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::sqrt, pow(a, 2)), r::equal, call(op::abs, a)};
         }},
        {"log_product", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::log, a * b), r::equal, call(op::log, a) + call(op::log, b)};
         }},
        {"log_quotient", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::log, a / b), r::equal, call(op::log, a) - call(op::log, b)};
         }},
        {"exp_of_log", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::exp, call(op::log, a)), r::equal, a};
         }},
        {"log_of_exp", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::log, call(op::exp, a)), r::equal, a};
         }},
        {"cube_of_cube_root", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(pow(a, 1, 3), 3), r::equal, a};
         }},
        {"cube_root_of_cube", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(pow(a, 3), 1, 3), r::equal, a};
         }},
        {"sixth_root_of_square", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(pow(a, 2), 1, 6), r::equal, pow(call(op::abs, a), 1, 3)};
         }},
        {"root_product", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::sqrt, a) * call(op::sqrt, b), r::equal, call(op::sqrt, a * b)};
         }},
        {"root_quotient", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::sqrt, a / b), r::equal, call(op::sqrt, a) / call(op::sqrt, b)};
         }},
        {"abs_product", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::abs, a * b), r::equal, call(op::abs, a) * call(op::abs, b)};
         }},
        {"exp_sum", false, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::exp, a + b), r::equal, call(op::exp, a) * call(op::exp, b)};
         }},
        {"root_squared", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(call(op::sqrt, a), 2), r::equal, a};
         }},
        {"three_halves", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(a, 3, 2), r::equal, a * call(op::sqrt, a)};
         }},
        {"fractions", false, [](const term& a, const term& b, const term& c, drawer& draw) {
             const term d = draw.draw(1);
             return relation_claim{a / b + c / d, r::equal, (a * d + b * c) / (b * d)};
         }},
        {"reciprocal", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{num(1) / (num(1) / a), r::equal, a};
         }},
        {"log_of_square", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::log, pow(a, 2)), r::equal, num(2) * call(op::log, call(op::abs, a))};
         }},
        {"powers", false, [](const term& a, const term&, const term&, drawer& draw) {
             const int m = static_cast<int>(draw.below(7)) - 3, n = static_cast<int>(draw.below(7)) - 3;
             return relation_claim{pow(a, m) * pow(a, n), r::equal, pow(a, m + n)};
         }},
        {"abs_squared", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(call(op::abs, a), 2), r::equal, pow(a, 2)};
         }},
        {"exp_squared", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(call(op::exp, a), 2), r::equal, call(op::exp, num(2) * a)};
         }},
        {"root_of_fourth_power", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::sqrt, pow(a, 4)), r::equal, pow(a, 2)};
         }},
        {"root_of_root_to_the_fourth", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(call(op::sqrt, a), 4), r::equal, pow(a, 2)};
         }},
        {"two_thirds", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(a, 2, 3), r::equal, pow(pow(a, 1, 3), 2)};
         }},
        {"inverse_root", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(a, -1, 2), r::equal, num(1) / call(op::sqrt, a)};
         }},
        {"root_times_root", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::sqrt, a) * call(op::sqrt, a), r::equal, a};
         }},
        {"log_of_root", false, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::log, call(op::sqrt, a)), r::equal, call(op::log, a) / num(2)};
         }},
        // Inequalities.
        {"root_below_mean", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::sqrt, a), r::less_equal, (a + num(1)) / num(2)};
         }},
        {"abs_above", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::abs, a), r::greater_equal, a};
         }},
        {"sum_of_squares", true, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{pow(a, 2) + pow(b, 2), r::greater_equal, num(0)};
         }},
        {"exp_positive", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::exp, a), r::greater, num(0)};
         }},
        {"abs_nonnegative", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::abs, a), r::greater_equal, num(0)};
         }},
        {"root_nonnegative", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::sqrt, a), r::greater_equal, num(0)};
         }},
        {"cube_root_nonnegative", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(a, 1, 3), r::greater_equal, num(0)};
         }},
        {"two_products", true, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{pow(a, 2) + pow(b, 2), r::greater_equal, num(2) * a * b};
         }},
        {"triangle", true, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::abs, a + b), r::less_equal, call(op::abs, a) + call(op::abs, b)};
         }},
        {"exp_above_tangent", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::exp, a), r::greater_equal, num(1) + a};
         }},
        {"log_below_tangent", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::log, a), r::less_equal, a - num(1)};
         }},
        {"square_of_difference", true, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{pow(a - b, 2), r::greater_equal, num(0)};
         }},
        {"square_plus_one", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{pow(a, 2) + num(1), r::greater, num(0)};
         }},
        {"hypotenuse", true, [](const term& a, const term& b, const term&, drawer&) {
             return relation_claim{call(op::sqrt, pow(a, 2) + pow(b, 2)), r::greater_equal, call(op::abs, a)};
         }},
        {"cosh_bound", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{call(op::exp, a) + call(op::exp, -a), r::greater_equal, num(2)};
         }},
        {"reciprocal_bound", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{num(1) / (pow(a, 2) + num(1)), r::less_equal, num(1)};
         }},
        {"inverse_square", true, [](const term& a, const term&, const term&, drawer&) {
             return relation_claim{num(1) / pow(a, 2), r::greater, num(0)};
         }},
    };
    return all;
}

// Every node of a term, for a perturbation to pick one.
void nodes(term& t, std::vector<term*>& out)
{
    out.push_back(&t);
    for (term& a : t.args)
        nodes(a, out);
}

// One node changed: a coefficient, a sign, an exponent, a function.
void mutate(term& side, drawer& draw)
{
    std::vector<term*> all;
    nodes(side, all);
    term& t = *all[draw.below(all.size())];
    switch (t.what) {
    case op::number: t.value = draw.chance(50) ? t.value + 1 : -t.value - 1; break;
    case op::symbol: t = t + num(1); break;
    case op::add: t.what = op::sub; break;
    case op::sub: t.what = op::add; break;
    case op::mul: t.what = op::add; break;
    case op::div: t.what = op::mul; break;
    case op::pow:
        if (t.args[1].what == op::number)
            t.args[1].value = t.args[1].value + 1;
        else
            t = num(2) * t;
        break;
    case op::neg: t = t.args[0]; break;
    case op::sqrt: t.what = op::abs; break;
    case op::abs: t = -t; break;
    default: t = num(2) * t; break;
    }
}

relation negated(relation r)
{
    switch (r) {
    case relation::equal: return relation::not_equal;
    case relation::not_equal: return relation::equal;
    case relation::less: return relation::greater_equal;
    case relation::less_equal: return relation::greater;
    case relation::greater: return relation::less_equal;
    case relation::greater_equal: return relation::less;
    }
    return r;
}

relation reversed(relation r)
{
    switch (r) {
    case relation::less: return relation::greater;
    case relation::less_equal: return relation::greater_equal;
    case relation::greater: return relation::less;
    case relation::greater_equal: return relation::less_equal;
    default: return r;
    }
}

void perturb(relation_claim& c, drawer& draw)
{
    const int pick = static_cast<int>(draw.below(100));
    if (c.rel != relation::equal && pick < 35) {
        c.rel = draw.chance(50) ? negated(c.rel) : reversed(c.rel);
    } else if (c.rel == relation::equal && pick < 40) {
        const int how = static_cast<int>(draw.below(3));
        c.rhs = how == 0 ? c.rhs + num(1) : how == 1 ? num(2) * c.rhs : -c.rhs;
    } else {
        mutate(draw.chance(50) ? c.lhs : c.rhs, draw);
    }
}

} // namespace

drawn_file draw_file(std::mt19937_64& rng, std::size_t claims)
{
    static const char* const domains[] = {"real", "real", "real", "positive", "positive", "nonnegative",
                                          "[0, 1]", "(-1, 2]", "[-1, 1]", "(0, 1)", "[1, 3]", "[-2, -1/2]"};
    static const char* const names[] = {"x", "y", "z", "w"};
    drawn_file f;
    const std::size_t count = 2 + rng() % 3;
    std::vector<std::string> leaves;
    for (std::size_t i = 0; i < count; ++i) {
        f.symbols.emplace_back(names[i], domains[rng() % (sizeof domains / sizeof *domains)]);
        leaves.push_back(names[i]);
    }
    drawer draw(rng, leaves);
    if (draw.chance(15)) {
        f.abbreviation_value = draw.draw(1);
        draw.names_.push_back("A");
    }
    if (draw.chance(25)) {
        f.defined_name = "D";
        f.defined_value = draw.draw(2);
        draw.names_.push_back("D");
    }
    for (std::size_t i = 0; i < claims; ++i) {
        const family& fam = families()[draw.below(families().size())];
        const int depth = 1 + static_cast<int>(draw.below(2));
        const term a = draw.draw(depth), b = draw.draw(depth), c = draw.draw(1);
        drawn_claim d{"c" + std::to_string(i + 1), fam.name, fam.make(a, b, c, draw), true, ""};
        if (draw.chance(40)) {
            perturb(d.claim, draw);
            d.true_by_construction = false;
        }
        if (draw.chance(15))
            d.through_step = "S" + std::to_string(i + 1);
        f.claims.push_back(std::move(d));
    }
    return f;
}

std::string drawn_file::toml() const
{
    std::string out = "id = \"soundness\"\ntitle = \"drawn by the soundness fuzzer\"\n";
    for (const auto& [name, domain] : symbols)
        out += "[[symbol]]\nname = \"" + name + "\"\ndomain = \"" + domain + "\"\n";
    if (abbreviation_value)
        out += "[[symbol]]\nname = \"A\"\ndefinition = \"" + text(*abbreviation_value) + "\"\n";
    const std::string result = defined_name.empty() ? "R" : defined_name;
    out += "[[symbol]]\nname = \"" + result + "\"\n";
    out += "[[step]]\ndefine = \"" + result + "\"\nas = \"" +
           (defined_name.empty() ? symbols.front().first : text(defined_value)) + "\"\nbecause = \"drawn\"\n";
    for (const drawn_claim& c : claims)
        if (!c.through_step.empty())
            out += "[[symbol]]\nname = \"" + c.through_step + "\"\n[[step]]\ndefine = \"" + c.through_step +
                   "\"\nas = \"" + text(c.claim.lhs) + "\"\nbecause = \"drawn\"\n";
    out += "[[result]]\nname = \"" + result + "\"\n";
    for (const drawn_claim& c : claims) {
        out += "# " + c.family + (c.true_by_construction ? ", true by construction" : ", perturbed") + "\n";
        const std::string claim = c.through_step.empty()
                                      ? text(c.claim)
                                      : text(relation_claim{term::symbol(c.through_step), c.claim.rel, c.claim.rhs});
        out += "[[check]]\nname = \"" + c.name + "\"\nclaim = \"" + claim + "\"\n";
    }
    return out;
}

} // namespace impact::soundness

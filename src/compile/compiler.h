// The compiler of a program's outputs (compile_program, compile/program.h), shared by its
// two halves: the plain arithmetic of an expression, operation by operation, and the
// value caches, branches and instructions (compiler.cpp); and the compensated arithmetic,
// each value a pair hi + lo (compensated.cpp).
#pragma once

#include "compile/program.h"

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace impact::compile::detail {

class compiler {
public:
    compiler(program& p, const engine::term_order& order, compile_options options, const let_values& lets);

    void set_options(compile_options options) { options_ = options; }

    int output(const GiNaC::ex& e);
    int value(const GiNaC::ex& e);
    int options_key() const;

private:
    // Compensated arithmetic: a value carried as hi + lo (lo < 0 means lo = 0), with the
    // error-free transformations TwoSum and TwoProduct (through std::fma), so that an
    // expression comes out within about one rounding of its exact value. A sum is
    // renormalised (it may cancel, leaving lo as large as hi); a product or quotient is
    // not (its lo is within an ulp of hi, all the next operation needs). A value is rounded
    // to one double, hi + lo, only where it leaves the compensated arithmetic.
    struct pair {
        int hi;
        int lo = -1;
    };

    // compensated.cpp
    int add_lo(int a, int b);
    int rounded(pair a);
    pair fast_two_sum(int s, int e);
    pair sum_with_lo(int s, int e, int lo);
    pair dd_add(pair a, pair b);
    pair dd_sub(pair a, pair b);
    pair dd_neg(pair a);
    pair dd_mul(pair a, pair b);
    pair dd_div(pair a, pair b);
    pair dd_sqrt(pair a);
    pair dd_constant(const GiNaC::numeric& n);
    pair compensated(const GiNaC::ex& e);
    pair compute_pair(const GiNaC::ex& e);
    pair compensated_factor(const engine::term_order::power_term& t);
    pair compensated_in_branch(int condition, bool positive, const GiNaC::ex& e);

    // compiler.cpp
    int in_branch(int condition, bool positive, const GiNaC::ex& e);
    void enter_branch(int condition, bool positive);
    void leave_branch();
    int emit(instruction in);
    int op(opcode code, int a, int b = -1, int c = -1);
    int constant(const GiNaC::numeric& n);
    int pi();
    int call(const std::string& function, std::vector<int> arguments);
    int compute(const GiNaC::ex& e);
    static std::string order_symbolless(const GiNaC::ex& e);
    int sum(const GiNaC::ex& e);
    int product(const GiNaC::ex& e);
    int product_of(const std::vector<engine::term_order::power_term>& factors);
    int factor(const engine::term_order::power_term& t);
    int power(const engine::term_order::power_term& t);

    program& p_;
    const engine::term_order& order_;
    compile_options options_;
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> inputs_;
    std::map<int, std::map<GiNaC::ex, int, GiNaC::ex_is_less>> known_;
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> lets_;
    std::map<int, std::map<GiNaC::ex, pair, GiNaC::ex_is_less>> known_pairs_;
    std::map<GiNaC::numeric, int, std::less<>> constants_;
    std::map<std::tuple<int, int, int, int>, int> ops_;
    int pi_ = -1;  // the constant π, once computed
    bool correcting_ = false;  // the operations made now are corrections
    bool in_condition_ = false;  // compiling the condition of cases, compensated without divisions
    std::vector<std::pair<int, bool>> branch_;  // the branches being compiled: condition, taken where positive
    std::map<std::vector<std::pair<int, bool>>, int> branch_keys_;
    int branch_key_ = 0;       // 0 outside every branch
    std::vector<int> outer_keys_;
};

} // namespace impact::compile::detail

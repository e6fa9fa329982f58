// The derivation's parts as stored text: its givens, cases, checks (each with its parts),
// solutions, steps, comparisons with the paper and results.
#include "engine/store/stored_codec.h"

namespace impact::engine {

using namespace stored_detail;

// ---- the derivation's parts ----

json derivation_codec::put_equation(const equation& e)
{
    return {e.name, put(e.relation), e.because, e.paper, put_where(e.where), put_written(e.written)};
}

void derivation_codec::get_equation(const json& j, equation& e)
{
    e.name = j.at(0).get<std::string>();
    e.relation = get(j.at(1));
    e.because = j.at(2).get<std::string>();
    e.paper = j.at(3).get<std::string>();
    e.where = get_where(j.at(4));
    get_written(j.at(5), e.written);
}

json derivation_codec::put_case(const case_value& c)
{
    return {code(c.op),          put(c.lhs),          put(c.rhs),        put(c.value),
            put(c.written_lhs),  put(c.written_rhs),  put(c.as_written), put_written(c.written),
            put_where(c.where)};
}

void derivation_codec::get_case(const json& j, case_value& c)
{
    c.op = enum_of<relation>(j.at(0), 4);
    c.lhs = get(j.at(1));
    c.rhs = get(j.at(2));
    c.value = get(j.at(3));
    c.written_lhs = get(j.at(4));
    c.written_rhs = get(j.at(5));
    c.as_written = get(j.at(6));
    get_written(j.at(7), c.written);
    c.where = get_where(j.at(8));
}

json derivation_codec::put_part(const check_result::part& p)
{
    json in_cases = json::array();
    for (const auto& [symbol, c] : p.in_cases)
        in_cases.push_back({put(symbol), put_case(c)});
    return {p.under,
            put_verdict(p.outcome),
            p.first,
            p.second,
            p.in_case ? put_case(*p.in_case) : json(),
            in_cases,
            p.boundary ? json{put(p.boundary->first), put(p.boundary->second)} : json()};
}

void derivation_codec::get_part(const json& j, check_result::part& p)
{
    p.under = j.at(0).get<std::string>();
    get_verdict(j.at(1), p.outcome);
    p.first = j.at(2).get<std::size_t>();
    p.second = j.at(3).get<std::size_t>();
    if (!j.at(4).is_null()) {
        p.in_case.emplace();
        get_case(j.at(4), *p.in_case);
    }
    for (const json& c : j.at(5)) {
        p.in_cases.emplace_back(get(c.at(0)), case_value{});
        get_case(c.at(1), p.in_cases.back().second);
    }
    if (!j.at(6).is_null())
        p.boundary.emplace(get(j.at(6).at(0)), get(j.at(6).at(1)));
}

json derivation_codec::put_check(const check_result& c)
{
    json assuming = json::array();
    for (const auto& [e, words] : c.assuming)
        assuming.push_back({put(e), words});
    return {c.name,
            c.statement,
            put(c.stated),
            put_pairs(c.at),
            put_pairs(c.left_at),
            code(c.op),
            c.limit ? json{put(c.limit->symbol), put(c.limit->point), c.limit->to_infinity} : json(),
            assuming,
            put_optional(c.value),
            c.limit_by ? put_limit_method(*c.limit_by) : json(),
            c.display_of,
            c.because,
            put(c.lhs),
            put(c.rhs),
            put_verdict(c.outcome),
            put_where(c.where),
            put_written(c.written),
            list(c.parts, &derivation_codec::put_part),
            c.cases_of,
            c.continuity,
            c.said_false,
            c.fails_at ? json{put_pairs(c.fails_at->point), put(c.fails_at->lhs), put(c.fails_at->rhs),
                              c.fails_at->exact}
                       : json()};
}

void derivation_codec::get_check(const json& j, check_result& c)
{
    c.name = j.at(0).get<std::string>();
    c.statement = j.at(1).get<std::string>();
    c.stated = get(j.at(2));
    c.at = get_pairs(j.at(3));
    c.left_at = get_pairs(j.at(4));
    c.op = enum_of<relation>(j.at(5), 4);
    if (!j.at(6).is_null())
        c.limit = check_result::limit_point{get(j.at(6).at(0)), get(j.at(6).at(1)), j.at(6).at(2).get<bool>()};
    for (const json& a : j.at(7))
        c.assuming.emplace_back(get(a.at(0)), a.at(1).get<std::string>());
    c.value = get_optional(j.at(8));
    if (!j.at(9).is_null()) {
        c.limit_by.emplace();
        get_limit_method(j.at(9), *c.limit_by);
    }
    c.display_of = j.at(10).get<std::string>();
    c.because = j.at(11).get<std::string>();
    c.lhs = get(j.at(12));
    c.rhs = get(j.at(13));
    get_verdict(j.at(14), c.outcome);
    c.where = get_where(j.at(15));
    get_written(j.at(16), c.written);
    get_list(j.at(17), c.parts, &derivation_codec::get_part);
    c.cases_of = j.at(18).get<std::string>();
    c.continuity = j.at(19).get<bool>();
    c.said_false = j.at(20).get<bool>();
    if (!j.at(21).is_null())
        c.fails_at = counterexample{get_pairs(j.at(21).at(0)), get(j.at(21).at(1)), get(j.at(21).at(2)),
                                    j.at(21).at(3).get<bool>()};
}

json derivation_codec::put_solution(const solution& s)
{
    return {put_pairs(s.values), code(s.outcome), put(s.unknown), put_domain(s.range),
            put(s.condition),   s.why,           list(s.proof, &derivation_codec::put_sign_step)};
}

void derivation_codec::get_solution(const json& j, solution& s)
{
    s.values = get_pairs(j.at(0));
    s.outcome = enum_of<solution::fate>(j.at(1), 2);
    s.unknown = get(j.at(2));
    s.range = get_domain(j.at(3));
    s.condition = get(j.at(4));
    s.why = j.at(5).get<std::string>();
    get_list(j.at(6), s.proof, &derivation_codec::get_sign_step);
}

json derivation_codec::put_step(const step_result& s)
{
    return {code(s.what),
            s.description,
            s.because,
            put_pairs(s.values),
            s.yields ? put_equation(*s.yields) : json(),
            put_exs(s.assumptions),
            list(s.checks, &derivation_codec::put_check),
            put_where(s.where),
            put_optional(s.as_written),
            put_written(s.written),
            list(s.solutions, &derivation_codec::put_solution),
            list(s.cases, &derivation_codec::put_case),
            put(s.cases_of),
            list(s.attached, &derivation_codec::put_condition),
            list(s.defined, &derivation_codec::put_condition)};
}

void derivation_codec::get_step(const json& j, step_result& s)
{
    s.what = enum_of<spec::step::kind>(j.at(0), 3);
    s.description = j.at(1).get<std::string>();
    s.because = j.at(2).get<std::string>();
    s.values = get_pairs(j.at(3));
    if (!j.at(4).is_null()) {
        s.yields.emplace();
        get_equation(j.at(4), *s.yields);
    }
    s.assumptions = get_exs(j.at(5));
    get_list(j.at(6), s.checks, &derivation_codec::get_check);
    s.where = get_where(j.at(7));
    s.as_written = get_optional(j.at(8));
    get_written(j.at(9), s.written);
    get_list(j.at(10), s.solutions, &derivation_codec::get_solution);
    get_list(j.at(11), s.cases, &derivation_codec::get_case);
    s.cases_of = get(j.at(12));
    get_list(j.at(13), s.attached, &derivation_codec::get_condition);
    get_list(j.at(14), s.defined, &derivation_codec::get_condition);
}

json derivation_codec::put_comparison(const paper_comparison& p)
{
    return {code(p.what),
            p.subject,
            p.paper,
            p.printed_text,
            put(p.printed),
            put(p.derived),
            put_verdict(p.agreement),
            list(p.findings, &derivation_codec::put_finding),
            p.reconciliations,
            p.test ? put_check(*p.test) : json(),
            put_where(p.where),
            put_written(p.written),
            p.quote,
            p.label};
}

void derivation_codec::get_comparison(const json& j, paper_comparison& p)
{
    p.what = enum_of<paper_comparison::kind>(j.at(0), 2);
    p.subject = j.at(1).get<std::string>();
    p.paper = j.at(2).get<std::string>();
    p.printed_text = j.at(3).get<std::string>();
    p.printed = get(j.at(4));
    p.derived = get(j.at(5));
    get_verdict(j.at(6), p.agreement);
    get_list(j.at(7), p.findings, &derivation_codec::get_finding);
    p.reconciliations = j.at(8).get<std::vector<std::string>>();
    if (!j.at(9).is_null()) {
        p.test.emplace();
        get_check(j.at(9), *p.test);
    }
    p.where = get_where(j.at(10));
    get_written(j.at(11), p.written);
    p.quote = j.at(12).get<std::string>();
    p.label = j.at(13).get<std::string>();
}

json derivation_codec::put_result(const result& r)
{
    return {r.name,
            put(r.symbol),
            put(r.value),
            put(r.display),
            r.paper,
            put_written(r.written),
            list(r.cases, &derivation_codec::put_case),
            list(r.attached, &derivation_codec::put_condition),
            list(r.defined, &derivation_codec::put_condition)};
}

void derivation_codec::get_result(const json& j, result& r)
{
    r.name = j.at(0).get<std::string>();
    r.symbol = get(j.at(1));
    r.value = get(j.at(2));
    r.display = get(j.at(3));
    r.paper = j.at(4).get<std::string>();
    get_written(j.at(5), r.written);
    get_list(j.at(6), r.cases, &derivation_codec::get_case);
    get_list(j.at(7), r.attached, &derivation_codec::get_condition);
    get_list(j.at(8), r.defined, &derivation_codec::get_condition);
}

} // namespace impact::engine

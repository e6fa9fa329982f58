#include "engine/expr/finding.h"

#include "engine/expr/symbols.h"

namespace impact::engine {

std::string plain_text(const finding& f, const symbol_table& symbols)
{
    std::string out;
    for (const finding::part& p : f.parts) {
        switch (p.what) {
        case finding::part::kind::words: out += p.words; break;
        case finding::part::kind::math:
            out += GiNaC::is_a<GiNaC::relational>(p.value)
                       ? symbols.text(p.value.lhs()) + " " + to_string(p.op) + " " + symbols.text(p.value.rhs())
                       : symbols.text(p.value);
            break;
        case finding::part::kind::tends:
            out += symbols.text(p.value) + " -> " + (p.point ? symbols.text(*p.point) : std::string("infinity"));
            break;
        case finding::part::kind::dimension: {
            // "a momentum (mass*length/time)", "1/mass", "a pure number"
            if (p.dim.is_pure_number()) {
                out += "a pure number";
                break;
            }
            const auto name = p.dim.familiar_name();
            out += name ? *name + " (" + p.dim.to_string() + ")" : p.dim.to_string();
            break;
        }
        }
    }
    return out;
}

std::vector<std::string> plain_texts(const std::vector<finding>& found, const symbol_table& symbols)
{
    std::vector<std::string> out;
    for (const finding& f : found)
        out.push_back(plain_text(f, symbols));
    return out;
}

} // namespace impact::engine

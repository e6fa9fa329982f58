#include "spec/latex_name.h"

#include <cctype>
#include <set>
#include <vector>

namespace impact::spec {

namespace {

bool is_greek(const std::string& word)
{
    static const std::set<std::string> greek = {
        "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu", "nu",
        "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega", "Gamma", "Delta", "Theta",
        "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega", "varepsilon", "vartheta", "varphi"};
    return greek.count(word) > 0;
}

bool all_digits(const std::string& word)
{
    if (word.empty())
        return false;
    for (const char c : word)
        if (!std::isdigit(static_cast<unsigned char>(c)))
            return false;
    return true;
}

// A word of the name as its symbol (`subscript` false) or as one of its subscripts.
std::string word_latex(const std::string& word, bool subscript)
{
    if (word == "eps")
        return "\\epsilon";
    if (is_greek(word))
        return "\\" + word;
    if (subscript && word == "perp")
        return "\\perp";
    if (subscript && word == "par")
        return "\\parallel";
    if (word.size() <= 1 || all_digits(word))
        return word;
    return (subscript ? "\\mathrm{" : "\\mathit{") + word + "}";
}

} // namespace

std::string latex_of_name(const std::string& name)
{
    std::string rest = name;
    bool primed = false;
    const std::string after = "_after";
    if (rest.size() > after.size() && rest.compare(rest.size() - after.size(), after.size(), after) == 0) {
        primed = true;
        rest.erase(rest.size() - after.size());
    }
    std::vector<std::string> words;
    for (std::size_t start = 0;;) {
        const auto underscore = rest.find('_', start);
        words.push_back(rest.substr(start, underscore == std::string::npos ? std::string::npos : underscore - start));
        if (underscore == std::string::npos)
            break;
        start = underscore + 1;
    }
    // Digits ending a name without subscripts: v1 is v_1, theta12 is theta_12.
    if (words.size() == 1) {
        std::size_t digits = words[0].size();
        while (digits > 0 && std::isdigit(static_cast<unsigned char>(words[0][digits - 1])))
            --digits;
        if (digits > 0 && digits < words[0].size()) {
            words.push_back(words[0].substr(digits));
            words[0].erase(digits);
        }
    }
    std::string out = word_latex(words[0], false) + (primed ? "'" : "");
    std::string subscripts;
    for (std::size_t i = 1; i < words.size(); ++i) {
        if (words[i].empty())
            continue;
        subscripts += (subscripts.empty() ? "" : ",") + word_latex(words[i], true);
    }
    if (!subscripts.empty())
        out += "_{" + subscripts + "}";
    return out;
}

} // namespace impact::spec

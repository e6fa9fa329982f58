#include "engine/references.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace impact::engine {

namespace {

std::string trimmed(const std::string& s)
{
    const auto first = s.find_first_not_of(" \t\n");
    const auto last = s.find_last_not_of(" \t\n");
    return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// A name's surname: its last word ("Mojca Čepič" → Čepič, "T Pöschel" → Pöschel).
std::string surname(const std::string& name)
{
    const std::string t = trimmed(name);
    const auto space = t.find_last_of(" ");
    return space == std::string::npos ? t : t.substr(space + 1);
}

// Case-insensitive for ASCII letters (BURACU and Buracu), bytes compared otherwise.
bool same_name(const std::string& a, const std::string& b)
{
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

// The years an entry prints: numbers of four digits from 1500 to 2099, not part of a longer number.
std::vector<int> years(const std::string& entry)
{
    std::vector<int> out;
    for (std::size_t i = 0; i < entry.size();) {
        if (!std::isdigit(static_cast<unsigned char>(entry[i]))) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < entry.size() && std::isdigit(static_cast<unsigned char>(entry[j])))
            ++j;
        if (j - i == 4) {
            const int year = std::stoi(entry.substr(i, 4));
            if (year >= 1500 && year <= 2099)
                out.push_back(year);
        }
        i = j;
    }
    return out;
}

std::string listing(const std::vector<std::string>& items)
{
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
    return out;
}

} // namespace

const char* to_string(text_comparison::outcome verdict)
{
    switch (verdict) {
    case text_comparison::outcome::agrees: return "agrees";
    case text_comparison::outcome::disagrees: return "disagrees";
    case text_comparison::outcome::undecided: return "undecided";
    }
    return "";
}

std::vector<std::string> reference_authors(const std::string& entry)
{
    // The authors end at the first period after a word of two letters or more.
    std::size_t end = std::string::npos;
    for (std::size_t i = entry.find('.'); i != std::string::npos; i = entry.find('.', i + 1)) {
        std::size_t start = i;
        while (start > 0 && entry[start - 1] != ' ' && entry[start - 1] != ',')
            --start;
        if (i - start >= 2) {
            end = i;
            break;
        }
    }
    std::string names = entry.substr(0, end);
    std::vector<std::string> out;
    // Split at ", and ", " and " and ",".
    std::size_t from = 0;
    while (from <= names.size()) {
        std::size_t comma = names.find(',', from), and_ = names.find(" and ", from);
        std::size_t cut = std::min(comma, and_);
        std::string name = trimmed(names.substr(from, cut == std::string::npos ? std::string::npos : cut - from));
        if (name.rfind("and ", 0) == 0)
            name = trimmed(name.substr(4));
        if (!name.empty())
            out.push_back(name);
        if (cut == std::string::npos)
            break;
        from = cut + (cut == comma ? 1 : 5);
    }
    return out;
}

std::vector<text_comparison> text_comparisons(const spec::derivation& d)
{
    std::vector<text_comparison> out;
    for (const spec::open_claim& c : d.open_claims)
        out.push_back({text_comparison::kind::claim, c.name.value, c.paper.value, c.quote.value, text_comparison::outcome::undecided,
                       c.undecided.value, c.paper.where});
    for (const spec::reference& r : d.references) {
        text_comparison t{text_comparison::kind::reference, fmt::format("reference {}", r.number), r.paper.value, r.entry.value,
                          text_comparison::outcome::agrees, "", r.where};
        std::vector<std::string> faults, cited_at;
        const std::vector<std::string> authors = reference_authors(r.entry.value);
        for (const spec::citation& c : d.citations) {
            if (c.cites != r.number)
                continue;
            std::string at = c.paper.value;
            if (c.names) {
                const std::string named = surname(c.names->value);
                const bool listed = std::any_of(authors.begin(), authors.end(),
                                                [&](const std::string& a) { return same_name(surname(a), named); });
                if (!listed)
                    faults.push_back(fmt::format("{} cites it beside {}, whom it does not name among its authors ({})",
                                                 c.paper.value, c.names->value, listing(authors)));
                at += fmt::format(" (beside {})", c.names->value);
            }
            if (std::find(cited_at.begin(), cited_at.end(), at) == cited_at.end())
                cited_at.push_back(at);
        }
        if (cited_at.empty())
            faults.push_back(fmt::format("no place of the text or the notes cites it (its mark {} appears nowhere)",
                                         r.number));
        std::map<std::string, std::vector<std::string>> by_surname;
        for (const std::string& a : authors) {
            std::string key = surname(a);
            std::transform(key.begin(), key.end(), key.begin(),
                           [](char ch) { return static_cast<char>(std::tolower(static_cast<unsigned char>(ch))); });
            by_surname[key].push_back(a);
        }
        for (const std::string& a : authors) {
            std::string key = surname(a);
            std::transform(key.begin(), key.end(), key.begin(),
                           [](char ch) { return static_cast<char>(std::tolower(static_cast<unsigned char>(ch))); });
            auto found = by_surname.find(key);
            if (found != by_surname.end() && found->second.size() > 1) {
                const std::size_t times = found->second.size();
                faults.push_back(fmt::format("it names one author {} ({})",
                                             times == 2 ? std::string("twice") : fmt::format("{} times", times),
                                             listing(found->second)));
                by_surname.erase(found);
            }
        }
        if (authors.empty())
            faults.push_back("it names no author before its first period");
        if (years(r.entry.value).empty())
            faults.push_back("it prints no year");
        if (faults.empty()) {
            t.finding = fmt::format("cited at {}; its authors ({}) each named once, and its year {}", listing(cited_at),
                                    listing(authors), years(r.entry.value).back());
        } else {
            t.verdict = text_comparison::outcome::disagrees;
            t.finding = faults.front();
            for (std::size_t i = 1; i < faults.size(); ++i)
                t.finding += "; " + faults[i];
        }
        out.push_back(std::move(t));
    }
    return out;
}

} // namespace impact::engine

#include "engine/paper/references.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace impact::engine {

namespace {

std::string trimmed(const std::string& s)
{
    const auto first = s.find_first_not_of(" \t\n");
    const auto last = s.find_last_not_of(" \t\n");
    return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// The words of a name, split at spaces.
std::vector<std::string> words_of(const std::string& name)
{
    std::vector<std::string> out;
    std::string word;
    for (const char c : name + " ") {
        if (c == ' ') {
            if (!word.empty())
                out.push_back(word);
            word.clear();
        } else {
            word += c;
        }
    }
    return out;
}

// Letters of UTF-8 text: its bytes that start a character.
std::size_t letters(const std::string& text)
{
    return static_cast<std::size_t>(
        std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// The first letter of a name (one UTF-8 character), to tell Marie Curie from Pierre Curie.
std::string initial(const std::string& name)
{
    const std::string t = trimmed(name);
    std::size_t end = t.empty() ? 0 : 1;
    while (end < t.size() && (static_cast<unsigned char>(t[end]) & 0xC0) == 0x80)
        ++end;
    return t.substr(0, end);
}

std::string lowered(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(),
                   [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
    return s;
}

// Case-insensitive for ASCII letters (BURACU and Buracu), bytes compared otherwise.
bool same_name(const std::string& a, const std::string& b)
{
    return lowered(a) == lowered(b);
}

// The names of a list as written: "et al." left out, split at commas, " and " and " & "
// ("T Schwager, V Becker, and T Pöschel" → three).
std::vector<std::string> authors_in(std::string text)
{
    for (const char* tail : {" et al.", " et al"})
        if (const auto at = text.find(tail); at != std::string::npos)
            text.erase(at);
    std::vector<std::string> out;
    for (std::size_t from = 0; from <= text.size();) {
        const std::size_t cut = std::min({text.find(',', from), text.find(" and ", from), text.find(" & ", from)});
        std::string name = trimmed(text.substr(from, cut == std::string::npos ? std::string::npos : cut - from));
        if (name.rfind("and ", 0) == 0)
            name = trimmed(name.substr(4));
        if (!name.empty())
            out.push_back(name);
        if (cut == std::string::npos)
            break;
        from = cut + (text[cut] == ',' ? 1 : text.compare(cut, 5, " and ") == 0 ? 5 : 3);
    }
    return out;
}

// The surnames the words beside a mark name: "Čepič's" → Čepič, "Schwager et al." →
// Schwager, "Schwager and Pöschel" → both.
std::vector<std::string> named_surnames(const std::string& names)
{
    std::vector<std::string> out;
    for (std::string name : authors_in(names)) {
        for (const std::string possessive : {"'s", "\u2019s"})
            if (name.size() > possessive.size() &&
                name.compare(name.size() - possessive.size(), std::string::npos, possessive) == 0)
                name.erase(name.size() - possessive.size());
        if (const std::vector<std::string> w = words_of(name); !w.empty())
            out.push_back(w.back());
    }
    return out;
}

// Whether an author's name holds `surname` as one of its words after the first ("Katica R
// Stevanović Hedrih" holds Stevanović and Hedrih), or is that one word.
bool has_surname(const std::string& author, const std::string& surname)
{
    const std::vector<std::string> w = words_of(author);
    for (std::size_t i = w.size() == 1 ? 0 : 1; i < w.size(); ++i)
        if (same_name(w[i], surname))
            return true;
    return false;
}

// The years an entry prints: numbers of four digits from 1500 to 2099, not part of a longer
// number nor of a range of pages (1596–1600, 63:1998).
std::vector<int> years(const std::string& entry)
{
    const auto at_range = [&](std::size_t i, std::size_t j) {
        const auto before = [&](const char* s) {
            const std::size_t n = std::string(s).size();
            return i >= n && entry.compare(i - n, n, s) == 0;
        };
        const auto after = [&](const char* s) { return entry.compare(j, std::string(s).size(), s) == 0; };
        return before("-") || before("\u2013") || before(":") || after("-") || after("\u2013");
    };
    std::vector<int> out;
    for (std::size_t i = 0; i < entry.size();) {
        if (!std::isdigit(static_cast<unsigned char>(entry[i]))) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < entry.size() && std::isdigit(static_cast<unsigned char>(entry[j])))
            ++j;
        if (j - i == 4 && !at_range(i, j)) {
            const int year = std::stoi(entry.substr(i, 4));
            if (year >= 1500 && year <= 2099)
                out.push_back(year);
        }
        i = j;
    }
    return out;
}

std::string listing(const std::vector<std::string>& items, const char* between = ", ")
{
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i == 0 ? "" : i + 1 == items.size() ? " and " : between) + items[i];
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
    // The authors end at the first period after a word of two letters or more, a word
    // starting after a space, a comma, a period or a hyphen ("J.-P. Bouchaud", "J.R.R.
    // Tolkien"), "et al." and "Jr." going on.
    std::size_t end = std::string::npos;
    for (std::size_t i = entry.find('.'); i != std::string::npos; i = entry.find('.', i + 1)) {
        std::size_t start = i;
        while (start > 0 && std::string(" ,.-").find(entry[start - 1]) == std::string::npos)
            --start;
        const std::string word = entry.substr(start, i - start);
        const bool goes_on = word == "Jr" || (word == "al" && start >= 3 && entry.compare(start - 3, 3, "et ") == 0);
        if (letters(word) >= 2 && !goes_on) {
            end = i;
            break;
        }
    }
    if (end == std::string::npos)
        return {};
    std::vector<std::string> out;
    for (const std::string& name : authors_in(entry.substr(0, end)))
        if (name != "Jr." && name != "Jr")
            out.push_back(name);
    return out;
}

std::vector<text_comparison> text_comparisons(const spec::derivation& d)
{
    std::vector<text_comparison> out;
    for (const spec::open_claim& c : d.open_claims)
        out.push_back({text_comparison::kind::claim, c.name.value, c.paper.value, c.quote.value,
                       text_comparison::outcome::undecided, c.undecided.value, c.paper.where});
    for (const spec::reference& r : d.references) {
        text_comparison t{text_comparison::kind::reference, fmt::format("reference {}", r.number), r.paper.value,
                          r.entry.value, text_comparison::outcome::agrees, "", r.where};
        std::vector<std::string> faults, cited_at;
        const std::vector<std::string> authors = reference_authors(r.entry.value);
        for (const spec::citation& c : d.citations) {
            if (c.cites != r.number)
                continue;
            std::string at = c.paper.value;
            if (c.names && !authors.empty()) {
                for (const std::string& named : named_surnames(c.names->value))
                    if (std::none_of(authors.begin(), authors.end(),
                                     [&](const std::string& a) { return has_surname(a, named); }))
                        faults.push_back(fmt::format("{} cites it beside {}, whom it does not name among its authors "
                                                     "({})",
                                                     c.paper.value, named, listing(authors)));
                at += fmt::format(" (beside {})", c.names->value);
            }
            if (std::find(cited_at.begin(), cited_at.end(), at) == cited_at.end())
                cited_at.push_back(at);
        }
        if (cited_at.empty())
            faults.push_back(fmt::format("no place of the text or the notes cites it (its mark {} appears nowhere)",
                                         r.number));
        if (authors.empty()) {
            faults.push_back("its authors are not set off by a period, as an entry's are");
        } else {
            // One author twice: the same surname and the same initial (Bernard Brogliato and
            // B Brogliato), where Marie and Pierre Curie are two.
            std::map<std::string, std::vector<std::string>> by_name;
            std::vector<std::string> order;
            for (const std::string& a : authors) {
                const std::vector<std::string> w = words_of(a);
                const std::string key = lowered(w.back()) + "|" + lowered(initial(a));
                if (by_name[key].empty())
                    order.push_back(key);
                by_name[key].push_back(a);
            }
            for (const std::string& key : order)
                if (const std::vector<std::string>& same = by_name[key]; same.size() > 1)
                    faults.push_back(fmt::format("it names one author {} ({})",
                                                 same.size() == 2 ? std::string("twice")
                                                                  : fmt::format("{} times", same.size()),
                                                 listing(same)));
        }
        const std::vector<int> printed_years = years(r.entry.value);
        if (printed_years.empty())
            faults.push_back("it prints no year");
        if (faults.empty()) {
            t.finding = fmt::format("cited at {}; its authors ({}) each named once, and its year {}",
                                    listing(cited_at, "; "), listing(authors), printed_years.back());
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

// The numbering of the report's labels as LaTeX numbers them, the anchors they become, and
// the scanning of TeX source the converter (html_tex.cpp) shares.
#include "report/html_parts.h"
#include "report/html_tex.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

namespace impact::report::html {

namespace detail {

bool starts(const std::string& s, std::size_t at, const char* prefix)
{
    return s.compare(at, std::char_traits<char>::length(prefix), prefix) == 0;
}

// The index just past the group `{...}` opening at `open` (braces balanced, \{ and \} skipped);
std::size_t group_end(const std::string& s, std::size_t open)
{
    int depth = 0;
    for (std::size_t i = open; i < s.size(); ++i) {
        if (s[i] == '\\') {
            ++i;
            continue;
        }
        if (s[i] == '{')
            ++depth;
        else if (s[i] == '}' && --depth == 0)
            return i + 1;
    }
    return std::string::npos;
}

// Splits `text` at each `separator` ("\\\\" or "&") outside braces and math.
std::vector<std::string> split_top(const std::string& text, const std::string& separator)
{
    std::vector<std::string> parts;
    std::string current;
    int depth = 0, environments = 0;
    bool math = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (text.compare(i, 7, "\\begin{") == 0)
            ++environments;
        else if (text.compare(i, 5, "\\end{") == 0)
            --environments;
        if (depth == 0 && environments == 0 && !math && text.compare(i, separator.size(), separator) == 0) {
            parts.push_back(current);
            current.clear();
            i += separator.size() - 1;
            continue;
        }
        if (c == '\\' && i + 1 < text.size()) {
            current += c;
            current += text[++i];
            continue;
        }
        if (c == '{')
            ++depth;
        else if (c == '}')
            --depth;
        else if (c == '$')
            math = !math;
        current += c;
    }
    parts.push_back(current);
    return parts;
}

std::string trimmed(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\n");
    if (b == std::string::npos)
        return "";
    return s.substr(b, s.find_last_not_of(" \t\n") - b + 1);
}

// Removes every `\command{...}` (and `\command*{...}` when `star`) from `row`, returning the
std::string take_command(std::string& row, const std::string& command)
{
    std::string first;
    bool found = false;
    for (std::size_t at; (at = row.find(command)) != std::string::npos;) {
        const std::size_t open = row.find('{', at);
        const std::size_t end = open == std::string::npos ? std::string::npos : group_end(row, open);
        if (end == std::string::npos)
            break;
        if (!found) {
            first = row.substr(open + 1, end - open - 2);
            found = true;
        }
        row.erase(at, end - at);
    }
    return first;
}

std::string plain_text(const std::string& html, const std::vector<formula>& formulas)
{
    std::string plain;
    bool in_tag = false;
    for (std::size_t i = 0; i < html.size(); ++i) {
        const char c = html[i];
        if (c == '\x02') {
            const std::size_t close = html.find('\x03', i);
            plain += formulas[std::stoul(html.substr(i + 1, close - i - 1))].tex;
            i = close;
        } else if (c == '<') {
            in_tag = true;
        } else if (c == '>') {
            in_tag = false;
        } else if (!in_tag) {
            plain += c;
        }
    }
    for (const auto& [entity, character] : {std::pair<const char*, const char*>{"&nbsp;", " "}, {"&lt;", "<"},
                                            {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}})
        for (std::size_t at; (at = plain.find(entity)) != std::string::npos;)
            plain.replace(at, std::char_traits<char>::length(entity), character);
    return plain;
}

} // namespace detail

using namespace detail;

std::string placeholder(std::size_t i)
{
    return fmt::format("\x02{}\x03", i);
}

std::string escaped(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (char c : text)
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    return out;
}

target place_of(const std::string& label)
{
    target t;
    if (starts(label, 0, "impact:")) {
        const std::string rest = label.substr(7);
        const std::size_t colon = rest.find(':');
        t.page = rest.substr(0, colon) + ".html";
        if (colon != std::string::npos) {
            t.anchor = rest.substr(colon + 1);
            std::replace(t.anchor.begin(), t.anchor.end(), ':', '-');
        }
        return t;
    }
    t.page = "index.html";
    t.anchor = starts(label, 0, "sec:") ? label.substr(4) : label;
    std::replace(t.anchor.begin(), t.anchor.end(), ':', '-');
    return t;
}

targets labels_of(const std::string& document, const std::map<std::string, std::string>& files)
{
    targets out;
    int section = 0, subsection = 0, figures = 0;
    std::string number;  // what \ref prints for a label here: the section's number
    std::string tag;     // the current row's \tag
    bool in_figure = false;
    // The document with each \input{latex/...} of a fragment walked in its place.
    std::vector<std::pair<const std::string*, std::size_t>> stack{{&document, 0}};
    while (!stack.empty()) {
        const std::string& s = *stack.back().first;
        std::size_t& i = stack.back().second;
        if (i >= s.size()) {
            stack.pop_back();
            continue;
        }
        if (s[i] != '\\') {
            ++i;
            continue;
        }
        auto argument = [&](std::size_t open) {
            const std::size_t close = group_end(s, open);
            const std::string text = close == std::string::npos ? "" : s.substr(open + 1, close - open - 2);
            i = close == std::string::npos ? s.size() : close;
            return text;
        };
        if (starts(s, i, "\\\\") || starts(s, i, "\\intertext") || starts(s, i, "\\end{align")) {
            tag.clear();
            i += 2;
        } else if (starts(s, i, "\\section{")) {
            number = std::to_string(++section);
            subsection = 0;
            i += 8;
        } else if (starts(s, i, "\\subsection{")) {
            number = fmt::format("{}.{}", section, ++subsection);
            i += 11;
        } else if (starts(s, i, "\\setcounter{figure}{")) {
            figures = std::atoi(argument(i + 19).c_str());
        } else if (starts(s, i, "\\begin{figure}")) {
            ++figures;
            in_figure = true;
            i += 14;
        } else if (starts(s, i, "\\end{figure}")) {
            in_figure = false;
            i += 12;
        } else if (starts(s, i, "\\tag*{")) {
            tag = argument(i + 5);
            for (std::size_t n; (n = tag.find('~')) != std::string::npos;)
                tag[n] = ' ';
        } else if (starts(s, i, "\\tag{")) {
            tag = argument(i + 4);
        } else if (starts(s, i, "\\label{")) {
            const std::string label = argument(i + 6);
            target t = place_of(label);
            t.text = in_figure ? std::to_string(figures) : !tag.empty() ? tag : number;
            out.emplace(label, t);
        } else if (starts(s, i, "\\input{")) {
            const std::string path = argument(i + 6);
            if (const auto found = files.find(path + ".tex"); found != files.end())
                stack.emplace_back(&found->second, 0);
        } else {
            ++i;
        }
    }
    return out;
}

} // namespace impact::report::html

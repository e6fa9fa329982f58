// Impact's LaTeX (report.tex and the derivations' fragments) as HTML: html_tex.h says what is
// converted and how.
#include "report/html_tex.h"
#include "report/html_parts.h"

#include "spec/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace impact::report::html {

namespace {

using namespace detail;

class converter {
public:
    converter(const std::string& tex, const std::string& name, const std::string& page_name, const targets& labels,
              input_handler* inputs, page& into)
        : s_(tex), name_(name), page_name_(page_name), labels_(labels), inputs_(inputs), p_(into)
    {
    }

    std::string blocks(std::size_t end, const std::string& environment, bool in_list);
    std::string inline_text(std::size_t begin, std::size_t end);

    std::size_t at = 0;

private:
    [[noreturn]] void fail(std::size_t where, const std::string& what) const
    {
        const auto line = static_cast<std::uint32_t>(std::count(s_.begin(), s_.begin() + static_cast<long>(std::min(where, s_.size())), '\n') + 1);
        throw error({name_, line, 0}, fmt::format("the HTML report cannot show {}", what));
    }

    std::string command_at(std::size_t i) const
    {
        std::size_t e = i + 1;
        while (e < s_.size() && std::isalpha(static_cast<unsigned char>(s_[e])))
            ++e;
        if (e == i + 1 && e < s_.size())
            ++e;
        return s_.substr(i + 1, e - i - 1);
    }

    // The argument `{...}` starting at `at` (after white space); `at` moves past it.
    std::pair<std::size_t, std::size_t> argument(std::size_t end)
    {
        while (at < end && (s_[at] == ' ' || s_[at] == '\n'))
            ++at;
        if (at >= end || s_[at] != '{')
            fail(at, "a command without its argument");
        const std::size_t close = group_end(s_, at);
        if (close == std::string::npos || close > end)
            fail(at, "an argument that is not closed");
        const std::pair<std::size_t, std::size_t> range{at + 1, close - 1};
        at = close;
        return range;
    }
    std::string raw_argument(std::size_t end)
    {
        const auto [b, e] = argument(end);
        return s_.substr(b, e - b);
    }
    void skip_optional(std::size_t end)
    {
        if (at < end && s_[at] == '[') {
            const std::size_t close = s_.find(']', at);
            if (close == std::string::npos || close > end)
                fail(at, "an optional argument that is not closed");
            at = close + 1;
        }
    }

    std::string anchor_attribute(const std::string& label) const
    {
        const target t = place_of(label);
        return t.anchor.empty() ? "" : fmt::format(" id=\"{}\"", escaped(t.anchor));
    }
    std::string link(const std::string& label, bool parenthesised, std::size_t where) const;
    std::string math(const std::string& tex, bool display)
    {
        p_.formulas.push_back({tex, display});
        return placeholder(p_.formulas.size() - 1);
    }
    std::string heading(const char* tag, std::size_t end);
    std::string list(const std::string& environment, std::size_t end);
    std::string align(const std::string& environment, std::size_t end);
    std::string table(std::size_t end);
    std::string figure(std::size_t end);
    std::string environment_end(const std::string& environment, std::size_t end, std::size_t& body_end);

    const std::string& s_;
    const std::string& name_;
    const std::string& page_name_;
    const targets& labels_;
    input_handler* inputs_;
    page& p_;
    bool skipping_else_ = false;
};

std::string converter::link(const std::string& label, bool parenthesised, std::size_t where) const
{
    const auto found = labels_.find(label);
    if (found == labels_.end())
        fail(where, "a reference to '" + label + "', which no label defines");
    const target& t = found->second;
    const std::string href = (t.page == page_name_ ? "" : t.page) + (t.anchor.empty() ? "" : "#" + t.anchor);
    const std::string text = escaped(t.text);
    return fmt::format("<a href=\"{}\">{}</a>", escaped(href.empty() ? "#" : href),
                       parenthesised ? "(" + text + ")" : text);
}

// The text between `begin` and `end` as inline HTML: text, math, emphasis, references.
std::string converter::inline_text(std::size_t begin, std::size_t end)
{
    std::string out;
    at = begin;
    while (at < end) {
        const char c = s_[at];
        if (c == '$') {
            std::size_t close = at + 1;
            while (close < end && (s_[close] != '$' || s_[close - 1] == '\\'))
                ++close;
            if (close >= end)
                fail(at, "a formula whose closing $ is missing");
            out += math(s_.substr(at + 1, close - at - 1), false);
            at = close + 1;
        } else if (c == '%') {
            const std::size_t eol = s_.find('\n', at);
            at = eol == std::string::npos || eol > end ? end : eol + 1;
        } else if (c == '{' || c == '}') {
            ++at;
        } else if (c == '~') {
            out += "&nbsp;";
            ++at;
        } else if (starts(s_, at, "``")) {
            out += "\u201c";
            at += 2;
        } else if (starts(s_, at, "''")) {
            out += "\u201d";
            at += 2;
        } else if (starts(s_, at, "---")) {
            out += "\u2014";
            at += 3;
        } else if (starts(s_, at, "--")) {
            out += "\u2013";
            at += 2;
        } else if (c == '\\') {
            const std::size_t where = at;
            const std::string command = command_at(at);
            at += 1 + command.size();
            if (command == "textbf" || command == "emph" || command == "textit" || command == "texttt") {
                const auto [b, e] = argument(end);
                const std::size_t after = at;
                const char* tag = command == "textbf" ? "strong" : command == "texttt" ? "code" : "em";
                out += fmt::format("<{0}>{1}</{0}>", tag, inline_text(b, e));
                at = after;
            } else if (command == "ref" || command == "eqref") {
                std::string label = raw_argument(end);
                if (label == "\\impacterratatable")
                    label = "sec:errata";
                out += link(label, command == "eqref", where);
            } else if (command == "label") {
                out += fmt::format("<span{}></span>", anchor_attribute(raw_argument(end)));
            } else if (command == "%" || command == "&" || command == "_" || command == "#" || command == "$" ||
                       command == "{" || command == "}") {
                out += escaped(command);
            } else if (command == "~" || command == "^" || command == "textbackslash" || command == "textless" ||
                       command == "textgreater" || command == "textbar") {
                // emit::latex_text's escapes of a character text-mode LaTeX takes otherwise.
                static const std::map<std::string, std::string> characters = {
                    {"~", "~"}, {"^", "^"}, {"textbackslash", "\\"}, {"textless", "&lt;"}, {"textgreater", "&gt;"},
                    {"textbar", "|"}};
                out += characters.at(command);
            } else if (command == ",") {
                out += "\u2009";
            } else if (command == " " || command == "\n") {
                out += " ";
            } else if (command == "\\" || command == "newline") {
                skip_optional(end);
                out += "<br>";
            } else if (command == "noindent" || command == "centering" || command == "footnotesize" ||
                       command == "large" || command == "small" || command == "raggedright") {
            } else if (command == "setlength" || command == "renewcommand" || command == "setcounter") {
                argument(end);
                argument(end);
            } else {
                fail(where, "the command \\" + command);
            }
        } else {
            const std::size_t next = s_.find_first_of("$%{}~`'-\\<>&\"", at + 1);
            const std::size_t stop = std::min(next == std::string::npos ? end : next, end);
            // One character of those that start something, when it starts nothing.
            out += escaped(s_.substr(at, std::max<std::size_t>(stop, at + 1) - at));
            at = std::max(stop, at + 1);
        }
    }
    return out;
}

std::string converter::heading(const char* tag, std::size_t end)
{
    const auto [b, e] = argument(end);
    const std::size_t after = at;
    const std::string text = inline_text(b, e);
    at = after;
    std::string id;
    std::size_t look = at;
    while (look < end && (s_[look] == ' ' || s_[look] == '\n'))
        ++look;
    if (starts(s_, look, "\\label{")) {
        at = look + 6;
        id = anchor_attribute(raw_argument(end));
    }
    if (p_.title.empty() && std::string(tag) != "h3") {
        p_.title = plain_text(text, p_.formulas);
    }
    return fmt::format("<{0}{1}>{2}</{0}>\n", tag, id, text);
}

// The index past `\end{environment}` from `at`, and where its body ends.
std::string converter::environment_end(const std::string& environment, std::size_t end, std::size_t& body_end)
{
    const std::string closing = "\\end{" + environment + "}";
    body_end = s_.find(closing, at);
    if (body_end == std::string::npos || body_end > end)
        fail(at, "\\begin{" + environment + "} without its \\end");
    return closing;
}

std::string converter::list(const std::string& environment, std::size_t end)
{
    const char* tag = environment == "enumerate" ? "ol" : "ul";
    std::string out = fmt::format("<{}>\n", tag);
    const std::string closing = "\\end{" + environment + "}";
    for (;;) {
        while (at < end && std::isspace(static_cast<unsigned char>(s_[at])))
            ++at;
        if (starts(s_, at, "\\setlength")) {
            at += 10;
            argument(end);
            argument(end);
            continue;
        }
        if (starts(s_, at, closing.c_str())) {
            at += closing.size();
            break;
        }
        if (!starts(s_, at, "\\item"))
            fail(at, "text in a list before its first \\item");
        at += 5;
        std::string label;
        if (at < end && s_[at] == '[') {
            const std::size_t close = s_.find(']', at);
            if (close == std::string::npos || close > end)
                fail(at, "an \\item label that is not closed");
            const std::size_t b = at + 1;
            label = inline_text(b, close);
            at = close + 1;
        }
        // An item's own \label (a check's) anchors the item.
        std::string id;
        if (starts(s_, at, "\\label{")) {
            at += 6;
            id = anchor_attribute(raw_argument(end));
        }
        const std::string body = blocks(end, environment, true);
        out += label.empty() ? fmt::format("<li{}>{}</li>\n", id, body)
                             : fmt::format("<li class=\"labelled\"{}><span class=\"item-label\">{}</span> {}</li>\n",
                                           id, label, body);
    }
    return out + fmt::format("</{}>\n", tag);
}

// A display of aligned rows: each run of rows ending in a \tag (or the last) one KaTeX
// `aligned` display, with its tag at the right and its label as the anchor; \intertext a
// paragraph between.
std::string converter::align(const std::string& environment, std::size_t end)
{
    std::size_t body_end = 0;
    const std::string closing = environment_end(environment, end, body_end);
    const std::size_t body_begin = at;
    const std::string body = s_.substr(body_begin, body_end - body_begin);
    at = body_end + closing.size();

    std::string out;
    std::vector<std::string> lines;
    auto flush = [&](const std::string& tag, bool starred, const std::string& label) {
        if (lines.empty())
            return;
        std::string tex = "\\begin{aligned}";
        for (std::size_t i = 0; i < lines.size(); ++i)
            tex += (i ? " \\\\ " : "") + lines[i];
        tex += "\\end{aligned}";
        std::string tag_html;
        if (!tag.empty()) {
            converter inner(tag, name_, page_name_, labels_, inputs_, p_);
            tag_html = inner.inline_text(0, tag.size());
            if (!starred)
                tag_html = "(" + tag_html + ")";
        }
        out += fmt::format("<div class=\"equation\"{}><div class=\"display\">{}</div>{}</div>\n",
                           label.empty() ? "" : anchor_attribute(label), math(tex, true),
                           tag_html.empty() ? "" : "<div class=\"tag\">" + tag_html + "</div>");
        lines.clear();
    };
    // The body in pieces: rows, and \intertext{...} between them.
    std::size_t from = 0;
    while (from <= body.size()) {
        const std::size_t inter = body.find("\\intertext{", from);
        const std::string rows = body.substr(from, (inter == std::string::npos ? body.size() : inter) - from);
        for (std::string row : split_top(rows, "\\\\")) {
            if (trimmed(row).empty())
                continue;
            std::string tag = take_command(row, "\\tag*");
            const bool starred = !tag.empty();
            if (!starred)
                tag = take_command(row, "\\tag");
            const std::string label = take_command(row, "\\label");
            const bool notag = row.find("\\notag") != std::string::npos;
            for (std::size_t n; (n = row.find("\\notag")) != std::string::npos;)
                row.erase(n, 6);
            lines.push_back(trimmed(row));
            if (!tag.empty() || !label.empty() || (!notag && environment == "align"))
                flush(tag, starred, label);
        }
        flush("", false, "");
        if (inter == std::string::npos)
            break;
        const std::size_t open = inter + 10;
        const std::size_t close = group_end(body, open);
        if (close == std::string::npos)
            fail(body_begin + inter, "an \\intertext that is not closed");
        out += "<p>" + inline_text(body_begin + open + 1, body_begin + close - 1) + "</p>\n";
        from = close;
    }
    at = body_end + closing.size();
    return out;
}

// The errata's longtable: its column specification skipped, the rows before \endhead the
// header, \toprule and the like dropped, each cell's text converted; each row's anchor made
// from its first cell (where in the paper), unique on the page.
std::string converter::table(std::size_t end)
{
    argument(end);  // the column specification
    std::size_t body_end = 0;
    const std::string closing = environment_end("longtable", end, body_end);
    const std::size_t body_begin = at;
    const std::string body = s_.substr(body_begin, body_end - body_begin);
    std::string head, rows;
    bool in_head = true;
    std::map<std::string, int> anchors;
    std::size_t offset = 0;
    for (const std::string& raw : split_top(body, "\\\\")) {
        const std::size_t row_begin = body_begin + offset;
        offset += raw.size() + 2;
        std::string row = raw;
        for (const char* rule : {"\\toprule", "\\midrule", "\\bottomrule", "\\endfoot"})
            for (std::size_t n; (n = row.find(rule)) != std::string::npos;)
                row.erase(n, std::char_traits<char>::length(rule));
        if (const std::size_t n = row.find("\\endhead"); n != std::string::npos) {
            row.erase(n, 8);
            in_head = false;
        }
        if (trimmed(row).empty())
            continue;
        const std::vector<std::string> cells = split_top(row, "&");
        std::string html;
        std::string first_text;
        for (std::size_t c = 0; c < cells.size(); ++c) {
            // Each cell converted on its own text (a copy: its line is the row's).
            converter inner(cells[c], name_, page_name_, labels_, inputs_, p_);
            std::string cell;
            try {
                cell = inner.inline_text(0, cells[c].size());
            } catch (const error& e) {
                fail(row_begin, e.message().substr(e.message().find("show ") + 5));
            }
            if (c == 0)
                first_text = cells[c];
            html += fmt::format(in_head ? "<th>{}</th>" : "<td>{}</td>", trimmed(cell));
        }
        if (in_head) {
            head += "<tr>" + html + "</tr>\n";
            continue;
        }
        // The anchor: the place in the paper, without its section reference, as a slug.
        std::string place = first_text.substr(0, first_text.find(" (Sect."));
        std::string slug;
        for (char ch : place) {
            if (std::isalnum(static_cast<unsigned char>(ch)))
                slug += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            else if (!slug.empty() && slug.back() != '-')
                slug += '-';
        }
        while (!slug.empty() && slug.back() == '-')
            slug.pop_back();
        const int n = ++anchors[slug];
        const std::string id = "errata-" + slug + (n > 1 ? fmt::format("-{}", n) : "");
        rows += fmt::format("<tr id=\"{}\">{}</tr>\n", id, html);
    }
    at = body_end + closing.size();
    return "<div class=\"table\"><table class=\"errata\">\n<thead>\n" + head + "</thead>\n<tbody>\n" + rows +
           "</tbody>\n</table></div>\n";
}

// A figure: its picture as SVG (figures/<name>.svg beside the page), its caption numbered.
std::string converter::figure(std::size_t end)
{
    skip_optional(end);
    std::size_t body_end = 0;
    const std::string closing = environment_end("figure", end, body_end);
    std::string image, caption, label;
    while (at < body_end) {
        if (std::isspace(static_cast<unsigned char>(s_[at]))) {
            ++at;
            continue;
        }
        if (starts(s_, at, "\\centering")) {
            at += 10;
        } else if (starts(s_, at, "\\includegraphics")) {
            at += 16;
            skip_optional(body_end);
            image = raw_argument(body_end);
        } else if (starts(s_, at, "\\caption")) {
            at += 8;
            const auto [b, e] = argument(body_end);
            const std::size_t after = at;
            caption = inline_text(b, e);
            at = after;
        } else if (starts(s_, at, "\\label")) {
            at += 6;
            label = raw_argument(body_end);
        } else {
            fail(at, "something in a figure other than its picture, caption and label");
        }
    }
    at = body_end + closing.size();
    if (image.empty())
        fail(body_end, "a figure without a picture");
    const auto number = labels_.find(label);
    const std::string prefix = number == labels_.end() ? "Figure" : "Figure " + number->second.text;
    return fmt::format("<figure{}>\n<a href=\"{}.svg\"><img src=\"{}.svg\" alt=\"{}\"></a>\n"
                       "<figcaption><strong>{}.</strong> {}</figcaption>\n</figure>\n",
                       label.empty() ? "" : anchor_attribute(label), escaped(image), escaped(image),
                       escaped(prefix), escaped(prefix), caption);
}

// Block-level HTML from `at` up to `end`, `\end{environment}` or, in a list, the next \item.
std::string converter::blocks(std::size_t end, const std::string& environment, bool in_list)
{
    std::string out, paragraph;
    std::size_t paragraph_begin = at;
    auto flush = [&] {
        if (paragraph_begin < at) {
            const std::size_t stop = at;
            const std::string text = trimmed(inline_text(paragraph_begin, stop));
            at = stop;
            if (!text.empty())
                out += in_list && out.empty() ? text + "\n" : "<p>" + text + "</p>\n";
        }
    };
    auto start_paragraph = [&] { paragraph_begin = at; };
    while (at < end) {
        const char c = s_[at];
        if (c == '\n') {
            std::size_t next = at + 1;
            while (next < end && (s_[next] == ' ' || s_[next] == '\t'))
                ++next;
            if (next < end && s_[next] == '\n') {
                flush();
                at = next + 1;
                start_paragraph();
                continue;
            }
            ++at;
            continue;
        }
        if (c == '%' && (at == 0 || s_[at - 1] != '\\')) {
            // A comment line: the text before it is a paragraph of its own only if blank
            // lines say so; skip it.
            flush();
            const std::size_t eol = s_.find('\n', at);
            at = eol == std::string::npos || eol >= end ? end : eol + 1;
            start_paragraph();
            continue;
        }
        if (c == '$') {
            // Past the formula, so that nothing inside it is taken for a block.
            std::size_t close = at + 1;
            while (close < end && (s_[close] != '$' || s_[close - 1] == '\\'))
                ++close;
            at = std::min(close + 1, end);
            continue;
        }
        if (c != '\\') {
            ++at;
            continue;
        }
        const std::string command = command_at(at);
        if (command == "item" && in_list)
            break;
        if (command == "end") {
            const std::size_t open = at + 4;
            const std::size_t close = group_end(s_, open);
            const std::string name = close == std::string::npos ? "" : s_.substr(open + 1, close - open - 2);
            if (name == environment) {
                flush();
                if (!in_list)
                    at = close;
                return out;
            }
            fail(at, "\\end{" + name + "} where it closes nothing");
        }
        const bool block = command == "begin" || command == "section" || command == "subsection" ||
                           command == "paragraph" || command == "tableofcontents" || command == "maketitle" ||
                           command == "input" || command == "ifdefined" || command == "else" || command == "fi" ||
                           command == "clearpage";
        if (!block) {
            at += 1 + command.size();
            continue;
        }
        flush();
        at += 1 + command.size();
        if (command == "section" || command == "subsection") {
            out += heading(command == "section" ? "h2" : "h1", end);
        } else if (command == "paragraph") {
            out += heading("h3", end);
        } else if (command == "tableofcontents") {
            out += "<!--contents-->\n";
        } else if (command == "maketitle") {
            out += "<!--title-->\n";
        } else if (command == "clearpage") {
        } else if (command == "input") {
            const std::string path = raw_argument(end);
            if (!inputs_)
                fail(at, "\\input{" + path + "}");
            out += inputs_->input(path, p_);
        } else if (command == "ifdefined") {
            // \ifdefined\impacterratatable: the page is read with the errata table beside it.
            const std::string macro = command_at(at);
            if (macro != "impacterratatable")
                fail(at, "\\ifdefined\\" + macro);
            at += 1 + macro.size();
            skipping_else_ = true;
        } else if (command == "else") {
            if (!skipping_else_)
                fail(at, "\\else without \\ifdefined");
            const std::size_t fi = s_.find("\\fi", at);
            if (fi == std::string::npos || fi > end)
                fail(at, "\\else without its \\fi");
            at = fi + 3;
            skipping_else_ = false;
        } else if (command == "fi") {
            skipping_else_ = false;
        } else {
            const std::string name = raw_argument(end);
            if (name == "itemize" || name == "enumerate")
                out += list(name, end);
            else if (name == "align" || name == "align*")
                out += align(name, end);
            else if (name == "longtable")
                out += table(end);
            else if (name == "figure")
                out += figure(end);
            else if (name == "document") {
            } else
                fail(at, "the environment " + name);
        }
        start_paragraph();
    }
    flush();
    return out;
}

} // namespace

page convert(const std::string& tex, const std::string& name, const std::string& page_name, const targets& labels,
             input_handler* inputs)
{
    page p;
    converter c(tex, name, page_name, labels, inputs, p);
    const std::size_t begin = tex.find("\\begin{document}");
    if (begin != std::string::npos)
        c.at = begin;
    const std::size_t end = tex.find("\\end{document}");
    p.html = c.blocks(end == std::string::npos ? tex.size() : end, "", false);
    return p;
}

} // namespace impact::report::html

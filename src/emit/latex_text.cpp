// Words in LaTeX: text escaped for the typesetter, and prose whose mathematics the
// derivation file writes between $...$ (emit/latex.h).
#include "emit/latex.h"

#include <string>

namespace impact::emit {

std::string latex_text(const std::string& text)
{
    std::string out;
    for (char ch : text) {
        switch (ch) {
        case '\\': out += "\\textbackslash{}"; break;
        case '_': case '%': case '&': case '#': case '$': case '{': case '}':
            out += '\\';
            out += ch;
            break;
        // OT1 accents, not the text companion's \textasciicircum (a bitmap font without cm-super).
        case '~': out += "\\~{}"; break;
        case '^': out += "\\^{}"; break;
        case '<': out += "\\textless{}"; break;
        case '>': out += "\\textgreater{}"; break;
        case '|': out += "\\textbar{}"; break;
        default: out += ch;
        }
    }
    return out;
}

std::string latex_prose(const std::string& text)
{
    // `$...$` is mathematics already; an unmatched `$` is a dollar sign.
    std::string out;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t open = text.find('$', at);
        const std::size_t close = open == std::string::npos ? open : text.find('$', open + 1);
        if (close == std::string::npos) {
            out += latex_text(text.substr(at));
            break;
        }
        out += latex_text(text.substr(at, open - at)) + text.substr(open, close - open + 1);
        at = close + 1;
    }
    return out;
}

} // namespace impact::emit

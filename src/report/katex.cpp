#include "report/katex.h"

#include "report/pdf.h"

#include "spec/error.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace impact::report::katex {

namespace fs = std::filesystem;

namespace {

// The script node runs: the formulas on its standard input, each `D` (displayed) or `I`
// (inline) and its TeX, ended by a NUL; on its standard output each one's HTML, or \x01 and
// KaTeX's message, ended by a NUL. Errors are not tolerated (throwOnError), so that no
// formula is shown as KaTeX's red source text.
constexpr const char* script = R"(const katex = require(process.argv[2]);
const items = require('fs').readFileSync(0, 'utf8').split('\0');
const out = [];
for (let i = 0; i + 1 < items.length; ++i) {
  try {
    out.push(katex.renderToString(items[i].slice(1), {displayMode: items[i][0] === 'D', throwOnError: true,
                                                      output: 'htmlAndMathml', strict: 'ignore', trust: false}));
  } catch (e) {
    out.push('\x01' + String(e.message).replace(/\0/g, ''));
  }
  out.push('\0');
}
process.stdout.write(out.join(''));
)";

} // namespace

std::string folder()
{
    const char* own = std::getenv("IMPACT_KATEX");
    return own && *own ? own : "/usr/share/javascript/katex";
}

std::optional<std::string> missing()
{
    if (std::system("node --version > /dev/null 2>&1") != 0)
        return std::string("Node.js is not installed (the web pages' formulas are typeset with KaTeX by node); "
                           "run scripts/setup.sh");
    if (!fs::exists(fs::path(folder()) / "katex.js"))
        return fmt::format("KaTeX is not installed ({}/katex.js is missing); run scripts/setup.sh, "
                           "or set IMPACT_KATEX to a folder holding katex.js",
                           folder());
    return std::nullopt;
}

const std::string& installation()
{
    static const std::string identity = [] {
        std::string text;
        if (FILE* pipe = ::popen("node --version 2>/dev/null", "r")) {
            char buffer[256];
            for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
                text.append(buffer, n);
            ::pclose(pipe);
        }
        const std::string js = read_file(fs::path(folder()) / "katex.js");
        return fmt::format("node {}katex.js of {} bytes: {}\n", text, js.size(), js.substr(0, 400));
    }();
    return identity;
}

std::vector<std::string> typeset(const std::vector<request>& formulas)
{
    if (const auto why = missing())
        throw error({"output/html", 0, 0}, *why);
    // Each distinct formula once.
    std::map<std::pair<std::string, bool>, std::size_t> index;
    std::vector<const request*> distinct;
    std::vector<std::size_t> of(formulas.size());
    for (std::size_t i = 0; i < formulas.size(); ++i) {
        const auto key = std::make_pair(formulas[i].formula.tex, formulas[i].formula.display);
        const auto [at, added] = index.emplace(key, distinct.size());
        if (added)
            distinct.push_back(&formulas[i]);
        of[i] = at->second;
    }
    const scratch_folder scratch("katex");
    std::string input;
    for (const request* r : distinct) {
        input += r->formula.display ? 'D' : 'I';
        input += r->formula.tex;
        input += '\0';
    }
    std::ofstream(scratch.path / "typeset.js", std::ios::binary) << script;
    std::ofstream(scratch.path / "formulas", std::ios::binary) << input;
    const std::string command = fmt::format("node '{}' '{}/katex.js' < '{}' > '{}' 2> '{}'",
                                            (scratch.path / "typeset.js").string(), folder(),
                                            (scratch.path / "formulas").string(),
                                            (scratch.path / "typeset").string(), (scratch.path / "errors").string());
    if (std::system(command.c_str()) != 0)
        throw error({"output/html", 0, 0},
                    fmt::format("KaTeX did not run: {}", single_line(read_file(scratch.path / "errors"))));
    const std::string output = read_file(scratch.path / "typeset");
    std::vector<std::string> typeset;
    for (std::size_t from = 0; from < output.size();) {
        const std::size_t end = output.find('\0', from);
        if (end == std::string::npos)
            break;
        typeset.push_back(output.substr(from, end - from));
        from = end + 1;
    }
    if (typeset.size() != distinct.size())
        throw error({"output/html", 0, 0}, fmt::format("KaTeX typeset {} of {} formulas", typeset.size(), distinct.size()));
    for (std::size_t d = 0; d < distinct.size(); ++d)
        if (!typeset[d].empty() && typeset[d][0] == '\x01')
            throw error({"output/html/" + distinct[d]->page, 0, 0},
                        fmt::format("the formula ${}$ cannot be typeset for the web page: {}",
                                    single_line(distinct[d]->formula.tex), single_line(typeset[d].substr(1))));
    std::vector<std::string> out;
    out.reserve(formulas.size());
    for (std::size_t i = 0; i < formulas.size(); ++i)
        out.push_back(typeset[of[i]]);
    return out;
}

std::map<std::string, std::string> assets()
{
    std::map<std::string, std::string> files;
    const fs::path root = folder();
    std::string css = read_file(root / "katex.min.css");
    // Each font in woff2 alone, which every current browser reads: the style sheet's other
    // sources (woff, ttf) dropped, so that it names no file the pages do not hold.
    for (std::size_t at = 0; (at = css.find(",url(fonts/", at)) != std::string::npos;) {
        const std::size_t end = css.find_first_of(";}", at);
        css.erase(at, end - at);
    }
    for (std::size_t at = 0; (at = css.find("url(fonts/", at)) != std::string::npos;) {
        const std::size_t end = css.find(')', at);
        const std::string name = css.substr(at + 4, end - at - 4);
        at = end;
        files["katex/" + name] = read_file(root / name);
    }
    files["katex/katex.min.css"] = css;
    return files;
}

} // namespace impact::report::katex

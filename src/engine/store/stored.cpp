// A derivation as text (stored.h): the derivation as a whole, written part by part by the
// codec (stored_codec.h) and read back, and its places, moved to where their lines are now
// when a file changed only by lines of comments or spaces.
#include "engine/store/stored.h"

#include "engine/store/stored_codec.h"

#include <algorithm>
#include <cstdint>
#include <string_view>

namespace impact::engine {

using namespace stored_detail;

namespace {

// The first line of every stored derivation: another format is never read.
constexpr const char* format_line = "impact derivation 1\n";

// The lines of a derivation file that hold more than spaces or a comment, each with its
// number (from 1), without the spaces that end it.
std::vector<std::pair<std::uint32_t, std::string_view>> content_lines(const std::string& text)
{
    std::vector<std::pair<std::uint32_t, std::string_view>> lines;
    std::uint32_t number = 0;
    for (std::size_t at = 0; at <= text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        std::string_view line(text.data() + at, end - at);
        ++number;
        while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r'))
            line.remove_suffix(1);
        const std::size_t first = line.find_first_not_of(" \t");
        if (first != std::string_view::npos && line[first] != '#')
            lines.emplace_back(number, line);
        at = end + 1;
    }
    return lines;
}

// Where each line of `before` is in `now` (0: a line of spaces or a comment), when the two
// differ only by such lines; nothing otherwise (a line changed, or moved).
std::optional<std::vector<std::uint32_t>> line_map(const std::string& before, const std::string& now)
{
    const auto a = content_lines(before), b = content_lines(now);
    if (a.size() != b.size())
        return std::nullopt;
    std::vector<std::uint32_t> map(static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n')) + 2, 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].second != b[i].second)
            return std::nullopt;
        map[a[i].first] = b[i].first;
    }
    return map;
}

} // namespace

// The derivation files' bytes now, by path: those of `source` and of `done`.
derivation_codec::derivation_codec(const spec::derivation& source, const derived_by_id& done)
{
    contents_[source.file] = &source.contents;
    for (const auto& [id, d] : done)
        contents_.emplace(d.source.file, &d.source.contents);
}

json derivation_codec::write(const derivation& d)
{
    for (const quantity& q : d.symbols.all())
        table_.emplace(q.symbol, table_.size());
    json out;
    out["symbols"] = put_symbols(d.symbols);
    out["givens"] = list(d.givens, &derivation_codec::put_equation);
    out["steps"] = list(d.steps, &derivation_codec::put_step);
    out["results"] = list(d.results, &derivation_codec::put_result);
    out["checks"] = list(d.checks, &derivation_codec::put_check);
    out["paper_checks"] = list(d.paper_checks, &derivation_codec::put_comparison);
    out["kernels"] = list(d.kernels, &derivation_codec::put_kernel);
    out["nodes"] = std::move(nodes_);
    out["temporaries"] = std::move(temporaries_);
    // Each file a place names, with its bytes when it is a derivation file: a comment
    // added or removed moves the places after it, which reading puts right.
    json files = json::array();
    for (const std::string& file : files_) {
        const auto bytes = contents_.find(file);
        files.push_back({file, bytes == contents_.end() ? json() : json(*bytes->second)});
    }
    out["files"] = std::move(files);
    return out;
}

derivation derivation_codec::read(const json& in, const spec::derivation& source)
{
    derivation d;
    d.source = source;
    for (const json& f : in.at("files")) {
        const std::string& file = f.at(0).get_ref<const std::string&>();
        if (f.at(1).is_null())
            continue;
        const auto now = contents_.find(file);
        if (now == contents_.end())
            throw not_readable("a place in a file not read now");
        const std::string& before = f.at(1).get_ref<const std::string&>();
        if (before == *now->second)
            continue;
        std::optional<std::vector<std::uint32_t>> moved = line_map(before, *now->second);
        if (!moved)
            throw not_readable("a file changed in more than its comments");
        lines_moved_[file] = std::move(*moved);
    }
    get_symbols(in.at("symbols"), d.symbols, source);
    nodes_in_ = &in.at("nodes");
    temporaries_in_ = &in.at("temporaries");
    built_.assign(nodes_in_->size(), std::nullopt);
    temporary_symbols_.assign(temporaries_in_->size(), std::nullopt);
    get_symbol_values(in.at("symbols"), d.symbols);
    get_list(in.at("givens"), d.givens, &derivation_codec::get_equation);
    get_list(in.at("steps"), d.steps, &derivation_codec::get_step);
    get_list(in.at("results"), d.results, &derivation_codec::get_result);
    get_list(in.at("checks"), d.checks, &derivation_codec::get_check);
    get_list(in.at("paper_checks"), d.paper_checks, &derivation_codec::get_comparison);
    get_list(in.at("kernels"), d.kernels, &derivation_codec::get_kernel);
    return d;
}

json derivation_codec::put_where(const source_location& w)
{
    files_.insert(w.file);
    return {w.file, w.line, w.column};
}

source_location derivation_codec::get_where(const json& j)
{
    source_location w{j.at(0).get<std::string>(), j.at(1).get<std::uint32_t>(), j.at(2).get<std::uint32_t>()};
    if (const auto moved = lines_moved_.find(w.file); moved != lines_moved_.end() && w.line != 0) {
        if (w.line >= moved->second.size() || moved->second[w.line] == 0)
            throw not_readable("a place on a line that is no longer there");
        w.line = moved->second[w.line];
    }
    return w;
}

std::optional<std::string> stored_derivation(const derivation& d, const derived_by_id& done)
{
    try {
        derivation_codec codec(d.source, done);
        return format_line + codec.write(d).dump();
    } catch (const not_storable&) {
        return std::nullopt;
    } catch (const json::exception&) {
        // A text that is not UTF-8 (a file name of other bytes): not kept.
        return std::nullopt;
    }
}

std::optional<derivation> restored_derivation(const std::string& text, const spec::derivation& source,
                                             const derived_by_id& done)
{
    const std::string header = format_line;
    if (text.compare(0, header.size(), header) != 0)
        return std::nullopt;
    try {
        const json in = json::parse(text.begin() + static_cast<std::ptrdiff_t>(header.size()), text.end());
        derivation_codec codec(source, done);
        return codec.read(in, source);
    } catch (const not_readable&) {
        return std::nullopt;
    } catch (const json::exception&) {
        return std::nullopt;
    } catch (const std::exception&) {
        // GiNaC's: a function no longer registered, a division by zero in a damaged text.
        return std::nullopt;
    }
}

} // namespace impact::engine

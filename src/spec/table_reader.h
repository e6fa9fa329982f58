// Walks one TOML table of a derivation file, remembering which keys were read so that a
// misspelt key is reported instead of silently ignored; every value it gives carries its
// place in the file. Used by the readers (reader.cpp, kernel_reader.cpp, outline.cpp) only.
#pragma once

#include "spec/derivation.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#define TOML_EXCEPTIONS 1
#include <toml++/toml.h>

namespace impact::spec::detail {

/// `s` without the blanks and tabs around it.
inline std::string trimmed(const std::string& s)
{
    const auto first = s.find_first_not_of(" \t");
    const auto last = s.find_last_not_of(" \t");
    return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

/// A place in the file from toml++'s region.
inline source_location location_of(const std::string& file, const toml::source_region& region)
{
    return {file, static_cast<std::uint32_t>(region.begin.line),
            static_cast<std::uint32_t>(region.begin.column)};
}

/// One table of the file (`[[given]]`, `[[kernel]]`, the top level), read key by key.
class table_reader {
public:
    table_reader(const toml::table& table, std::string file, std::string context)
        : table_(table), file_(std::move(file)), context_(std::move(context))
    {
    }

    source_location where() const { return location_of(file_, table_.source()); }

    bool has(std::string_view key) const { return table_.contains(key); }

    text required_string(std::string_view key)
    {
        const toml::node* node = find(key);
        if (!node)
            missing(key);
        return as_text(*node, key);
    }

    std::optional<text> optional_string(std::string_view key)
    {
        const toml::node* node = find(key);
        if (!node)
            return std::nullopt;
        return as_text(*node, key);
    }

    text string_or(std::string_view key, std::string fallback)
    {
        if (auto value = optional_string(key))
            return *value;
        return {std::move(fallback), where()};
    }

    std::vector<text> string_array(std::string_view key, bool required)
    {
        const toml::node* node = find(key);
        if (!node) {
            if (required)
                missing(key);
            return {};
        }
        const toml::array* array = node->as_array();
        if (!array)
            throw error(location_of(file_, node->source()),
                        fmt::format("'{}' in {} must be an array of strings", key, context_));
        std::vector<text> values;
        for (const toml::node& element : *array)
            values.push_back(as_text(element, key));
        return values;
    }

    // `name = expression` strings, e.g. kernel outputs `v_M = v_M_after`.
    std::vector<binding> binding_array(std::string_view key, bool required)
    {
        std::vector<binding> bindings;
        for (const text& entry : string_array(key, required))
            bindings.push_back(split_binding(entry, key));
        return bindings;
    }

    // A table of `name = "expression"` pairs, e.g. `at = { eps = "1" }`.
    std::vector<binding> binding_table(std::string_view key)
    {
        const toml::node* node = find(key);
        if (!node)
            return {};
        const toml::table* table = node->as_table();
        if (!table)
            throw error(location_of(file_, node->source()),
                        fmt::format("'{}' in {} must be a table such as {{ eps = \"1\" }}", key, context_));
        std::vector<binding> bindings;
        for (const auto& [name, value] : *table) {
            text expression = as_text(value, key);
            bindings.push_back({{std::string(name.str()), location_of(file_, name.source())},
                                std::move(expression)});
        }
        return bindings;
    }

    // An array of tables (`[[given]]` or `given = [{...}, ...]`).
    std::vector<const toml::table*> table_array(std::string_view key)
    {
        const toml::node* node = find(key);
        if (!node)
            return {};
        const toml::array* array = node->as_array();
        if (!array)
            throw error(location_of(file_, node->source()),
                        fmt::format("'{}' must be an array of tables ([[{}]])", key, key));
        std::vector<const toml::table*> tables;
        for (const toml::node& element : *array) {
            const toml::table* table = element.as_table();
            if (!table)
                throw error(location_of(file_, element.source()),
                            fmt::format("each entry of '{}' must be a table", key));
            tables.push_back(table);
        }
        return tables;
    }

    binding split(const text& entry, std::string_view key) const { return split_binding(entry, key); }

    double required_number(std::string_view key)
    {
        const toml::node* node = find(key);
        if (!node)
            missing(key);
        if (const auto value = node->value<double>())
            return *value;
        throw error(location_of(file_, node->source()), fmt::format("'{}' in {} must be a number", key, context_));
    }

    source_location where_of(std::string_view key) const
    {
        if (const toml::node* node = table_.get(key))
            return location_of(file_, node->source());
        return where();
    }

    /// A reader for a table inside this one (`[[kernel.bound]]`).
    table_reader nested(const toml::table& table, std::string context) const
    {
        return table_reader(table, file_, std::move(context));
    }

    std::optional<bool> optional_bool(std::string_view key)
    {
        const toml::node* node = find(key);
        if (!node)
            return std::nullopt;
        if (const auto* value = node->as_boolean())
            return value->get();
        throw error(location_of(file_, node->source()), fmt::format("'{}' in {} must be true or false", key, context_));
    }

    // Every key must have been read: an unknown key is most likely a typo.
    void finish() const
    {
        for (const auto& [key, value] : table_) {
            if (!read_.count(std::string(key.str())))
                throw error(location_of(file_, key.source()),
                            fmt::format("unknown field '{}' in {}", key.str(), context_));
        }
    }

private:
    // A required field not there: said where a key spelt nearly so stands (`titel` for
    // `title`, `becuase`), else at the table.
    [[noreturn]] void missing(std::string_view key) const
    {
        for (const auto& [other, value] : table_)
            if (!read_.count(std::string(other.str())) && key.size() >= 4 && nearly(other.str(), key))
                throw error(location_of(file_, other.source()),
                            fmt::format("unknown field '{}' in {}, which is missing the required field '{}': "
                                        "misspelt?",
                                        other.str(), context_, key));
        throw error(where(), fmt::format("{} is missing the required field '{}'", context_, key));
    }

    // At most two letters changed, added, dropped or swapped with the next.
    static bool nearly(std::string_view a, std::string_view b)
    {
        if (a.size() + 2 < b.size() || b.size() + 2 < a.size())
            return false;
        std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
        for (std::size_t i = 0; i <= a.size(); ++i)
            d[i][0] = i;
        for (std::size_t j = 0; j <= b.size(); ++j)
            d[0][j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i)
            for (std::size_t j = 1; j <= b.size(); ++j) {
                d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
                if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                    d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        return d[a.size()][b.size()] <= 2;
    }

    const toml::node* find(std::string_view key)
    {
        read_.insert(std::string(key));
        return table_.get(key);
    }

    text as_text(const toml::node& node, std::string_view key) const
    {
        const auto* value = node.as_string();
        if (!value)
            throw error(location_of(file_, node.source()),
                        fmt::format("'{}' in {} must be a string", key, context_));
        return {value->get(), location_of(file_, node.source())};
    }

    binding split_binding(const text& entry, std::string_view key) const
    {
        const auto equals = entry.value.find('=');
        if (equals == std::string::npos)
            throw error(entry.where, fmt::format("'{}' entry \"{}\" must read 'name = expression'",
                                                 key, entry.value));
        return {{trimmed(entry.value.substr(0, equals)), entry.where},
                {trimmed(entry.value.substr(equals + 1)), entry.where}};
    }

    const toml::table& table_;
    std::string file_;
    std::string context_;
    std::set<std::string> read_;
};

} // namespace impact::spec::detail

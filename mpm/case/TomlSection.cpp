#include "case/TomlSection.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.hpp"
#include "case/DidYouMean.hpp"

namespace qs {

std::string describe(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::string:
            return "a string " + inQuotes(node.as_string()->get());
        case toml::node_type::integer:
            return "an integer " + std::to_string(node.as_integer()->get());
        case toml::node_type::floating_point:
            return "a float " + number(node.as_floating_point()->get());
        case toml::node_type::boolean:
            return std::string("a boolean ") + (node.as_boolean()->get() ? "true" : "false");
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        default:
            return "a date/time value";
    }
}

int lineOfNode(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

Section::Section(const toml::table& root, const TableKeys& keys, const TableCatalogue& format,
                 KeyLocations& where)
    : Section(format, where, &root, "", keys, 1) {}

Section::Section(const TableCatalogue& format, KeyLocations& where, const toml::table* table,
                 std::string path, const TableKeys& keys, int fallbackLine)
    : format_(&format), where_(&where), table_(table), path_(std::move(path)), keys_(&keys),
      line_(fallbackLine) {
    if (table_ && lineOfNode(*table_) > 0) line_ = lineOfNode(*table_);
    if (table_) checkKeys();
    where_->addTable(path_, line_);
    if (table_)
        for (const auto& [key, node] : *table_) where_->addKey(path_, key.str(), lineOfNode(node));
}

std::string Section::keyPath(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const toml::node* Section::find(std::string_view key) const {
    QS_ASSERT(keys_->contains(key));
    return table_ ? table_->get(key) : nullptr;
}

int Section::lineOf(std::string_view key) const {
    QS_ASSERT(keys_->contains(key));
    return where_->table(path_).lineOf(key);
}

void Section::fail(std::string_view key, const std::string& what) const {
    QS_ASSERT(keys_->contains(key));
    where_->table(path_).fail(key, what);
}

void Section::missing(std::string_view key, const std::string& expected) const {
    fail(key, "missing required key '" + std::string(key) + "' in " + tableName() + " (expected " + expected + ")");
}

void Section::forbid(std::string_view key, const std::string& why) const {
    if (has(key)) fail(key, "'" + std::string(key) + "' has no effect here: " + why + ". Remove it");
}

std::optional<double> Section::optionalNumber(std::string_view key, const Range& range,
                                              const std::string& hint) const {
    const toml::node* node = find(key);
    if (!node) return std::nullopt;
    double v = 0.0;
    if (const auto* i = node->as_integer())
        v = static_cast<double>(i->get());
    else if (const auto* f = node->as_floating_point())
        v = f->get();
    else {
        std::string what = "expected a number (" + range.describe() + "), got " + describe(*node);
        if (const auto* s = node->as_string()) {
            std::istringstream probe(s->get());
            double x;
            if (probe >> x && probe.eof()) what += "; write numbers without quotes";
            else if (std::istringstream(s->get()) >> x)  // "50s", "2 kPa": a number with a unit
                what += "; write the number alone, in " + (range.unit.empty() ? std::string("SI units") : range.unit) +
                        " (units are SI and not written)";
        }
        fail(key, what);
    }
    if (!std::isfinite(v)) fail(key, "expected a finite number (" + range.describe() + "), got " + number(v));
    if (!range.contains(v))
        fail(key, "value " + number(v) + (range.unit.empty() ? "" : " " + range.unit) +
                      " is out of range: expected a value " + range.describe() + (hint.empty() ? "" : " (" + hint + ")"));
    return v;
}

double Section::requiredNumber(std::string_view key, const Range& range, const std::string& hint) const {
    if (!has(key)) missing(key, "a number " + range.describe() + (hint.empty() ? "" : ", " + hint));
    return *optionalNumber(key, range, hint);
}

int Section::integer(std::string_view key, int fallback, const Range& range) const {
    const toml::node* node = find(key);
    if (!node) return fallback;
    const auto* i = node->as_integer();
    if (!i) fail(key, "expected an integer (" + range.describe() + "), got " + describe(*node));
    const auto v = i->get();
    if (!range.contains(static_cast<double>(v)) || v > std::numeric_limits<int>::max() ||
        v < std::numeric_limits<int>::min())
        fail(key, "value " + std::to_string(v) + " is out of range: expected an integer " + range.describe() +
                      (std::isfinite(range.hi) ? "" : " and <= " + std::to_string(std::numeric_limits<int>::max())));
    return static_cast<int>(v);
}

bool Section::boolean(std::string_view key, bool fallback) const {
    const toml::node* node = find(key);
    if (!node) return fallback;
    const auto* b = node->as_boolean();
    if (!b) fail(key, "expected a boolean (true or false, without quotes), got " + describe(*node));
    return b->get();
}

std::optional<std::string> Section::optionalString(std::string_view key, bool allowEmpty) const {
    const toml::node* node = find(key);
    if (!node) return std::nullopt;
    const auto* s = node->as_string();
    if (!s) fail(key, "expected a string (in quotes), got " + describe(*node));
    if (!allowEmpty && s->get().empty()) fail(key, "expected a non-empty string, got \"\"");
    return s->get();
}

std::string Section::requiredString(std::string_view key, const std::string& expected) const {
    if (!has(key)) missing(key, expected);
    return *optionalString(key);
}

std::size_t Section::requiredChoiceIndex(std::string_view key, const std::vector<std::string>& names) const {
    if (!has(key)) missing(key, "one of " + joinQuoted(names));
    const toml::node* node = find(key);
    const auto* s = node->as_string();
    if (!s) fail(key, "expected one of " + joinQuoted(names) + ", got " + describe(*node));
    for (std::size_t k = 0; k < names.size(); ++k)
        if (s->get() == names[k]) return k;
    std::string what = "unknown value " + inQuotes(s->get()) + "; allowed: " + joinQuoted(names);
    if (auto guess = nearest(s->get(), names)) what += ". Did you mean " + inQuotes(*guess) + "?";
    fail(key, what);
}

Section Section::subsection(std::string_view key, const TableKeys& keys, bool required) const {
    const toml::node* node = find(key);
    if (!node) {
        if (required) fail(key, "missing required table [" + keyPath(key) + "]");
        return Section(*format_, *where_, nullptr, keyPath(key), keys, line_);
    }
    const toml::table* t = node->as_table();
    if (!t) fail(key, "expected a table [" + keyPath(key) + "], got " + describe(*node));
    return Section(*format_, *where_, t, keyPath(key), keys, line_);
}

Section Section::child(const toml::table& table, std::string path, const TableKeys& keys, int fallbackLine) const {
    return Section(*format_, *where_, &table, std::move(path), keys, fallbackLine);
}

const toml::array* Section::arrayOfTables(std::string_view key, bool required) const {
    const toml::node* node = find(key);
    if (!node) {
        if (required) fail(key, "missing required [[" + std::string(key) + "]] entries (at least one)");
        return nullptr;
    }
    const toml::array* a = node->as_array();
    if (!a)
        fail(key, "expected an array of tables, one [[" + std::string(key) + "]] header per entry, got " +
                      describe(*node));
    for (std::size_t i = 0; i < a->size(); ++i) {
        const toml::node& item = *a->get(i);
        if (!item.is_table()) {
            const int line = lineOfNode(item) > 0 ? lineOfNode(item) : lineOf(key);
            throw InputError(where_->file(), line, keyPath(key) + "[" + std::to_string(i) + "]",
                             "expected a table (write each entry as a [[" + std::string(key) +
                                 "]] header followed by its keys), got " + describe(item));
        }
    }
    if (required && a->empty()) fail(key, "expected at least one [[" + std::string(key) + "]] entry, got none");
    return a;
}

Section Section::entry(std::string_view key, std::size_t index, const TableKeys& keys) const {
    const toml::node* node = find(key);
    QS_ASSERT(node && node->is_array() && index < node->as_array()->size());
    return child(*node->as_array()->get(index)->as_table(), keyPath(key) + "[" + std::to_string(index) + "]", keys,
                 lineOf(key));
}

void Section::checkKeys() const {
    for (const auto& [k, node] : *table_) {
        const std::string_view key = k.str();
        if (keys_->contains(key)) continue;
        std::vector<std::string> candidates(keys_->first, keys_->last);
        std::string what = "unknown key '" + std::string(key) + "' in " + tableName() + ".";
        if (auto guess = nearest(key, candidates)) {
            what = "unknown key '" + std::string(key) + "'. Did you mean '" + *guess + "'?";
        } else {
            std::string elsewhere;
            for (const TableKeys* t : *format_)
                if (t != keys_ && t->contains(key)) {
                    elsewhere = t->title;
                    break;
                }
            if (!elsewhere.empty())
                what += " '" + std::string(key) + "' belongs in " + elsewhere +
                        (elsewhere == "the top level" ? " (before the first [table] header: a key "
                                                        "after a header belongs to that table)"
                                                      : "") +
                        ".";
            what += " Allowed keys: " + joinQuoted(candidates) + ".";
        }
        const int line = lineOfNode(node) > 0 ? lineOfNode(node) : line_;
        throw InputError(where_->file(), line, keyPath(key), what);
    }
}

}  // namespace qs

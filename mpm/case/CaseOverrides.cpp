// Command-line overrides of a case's keys (case/CaseOverride.hpp, case/CaseOverrides.hpp).
#include "case/CaseOverrides.hpp"

#include <algorithm>
#include <cctype>
#include <memory>
#include <map>
#include <optional>
#include <sstream>

#include "core/Error.hpp"

namespace qs {

namespace {

/// One step of a dotted key: a name, and an index if it names an element of an array of tables.
struct KeyStep {
    std::string name;
    std::optional<std::size_t> index;
};

[[noreturn]] void refuse(const std::string& fileName, const CaseOverride& o, const std::string& what) {
    throw InputError(fileName + ", " + o.text(), 0, o.key, what);
}

/// "layers[1].thickness" -> {layers, 1}, {thickness}
std::vector<KeyStep> splitKey(const std::string& fileName, const CaseOverride& o) {
    std::vector<KeyStep> steps;
    std::istringstream in(o.key);
    std::string part;
    while (std::getline(in, part, '.')) {
        KeyStep step;
        const auto bracket = part.find('[');
        step.name = part.substr(0, bracket);
        if (bracket != std::string::npos) {
            const auto close = part.find(']', bracket);
            const std::string digits = part.substr(bracket + 1, close == std::string::npos ? close : close - bracket - 1);
            const bool number = !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos;
            if (close != part.size() - 1 || !number)
                refuse(fileName, o, "'" + part + "' is not NAME or NAME[INDEX] (INDEX a whole number from 0)");
            step.index = std::stoul(digits);
        }
        const bool word = !step.name.empty() && std::all_of(step.name.begin(), step.name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
        });
        if (!word)
            refuse(fileName, o,
                   "expected a dotted key of names made of letters, digits, '_' and '-' (as in "
                   "docs/case-format.md: time.end, materials.sand.porosity, layers[1].thickness)");
        steps.push_back(step);
    }
    if (steps.empty() || o.key.back() == '.') refuse(fileName, o, "the key is empty or ends with '.'");
    return steps;
}

/// The value as TOML would read it; a bare word that is no TOML value is a string
std::unique_ptr<toml::node> parseValue(const std::string& text) {
    toml::table parsed;
#if TOML_EXCEPTIONS
    try {
        parsed = toml::parse("v = " + text);
    } catch (const toml::parse_error&) {
        return std::make_unique<toml::value<std::string>>(text);
    }
#else
    toml::parse_result result = toml::parse("v = " + text);
    if (!result) return std::make_unique<toml::value<std::string>>(text);
    parsed = std::move(result).table();
#endif
    std::unique_ptr<toml::node> copy;
    if (parsed.size() == 1)
        if (toml::node* v = parsed.get("v"))
            v->visit([&](auto&& n) { copy = std::make_unique<std::decay_t<decltype(n)>>(n); });
    if (!copy) copy = std::make_unique<toml::value<std::string>>(text);  // "1 \n w = 2": more than a value
    return copy;
}

/// How a node is written in TOML, on one line
std::string written(const toml::node& node) {
    std::ostringstream s;
    node.visit([&](auto&& n) {
        if constexpr (toml::is_table<decltype(n)> || toml::is_array<decltype(n)>)
            s << toml::toml_formatter(n, toml::format_flags::none);
        else
            s << n;
    });
    std::string text = s.str();
    for (char& c : text)
        if (c == '\n') c = ' ';
    return text;
}

}  // namespace

CaseOverride parseOverride(const std::string& argument) {
    const auto eq = argument.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error("--set " + argument + ": expected --set KEY=VALUE, KEY a dotted case key (time.end, "
                    "reservoir.area, layers[1].thickness; docs/case-format.md)");
    std::string key = argument.substr(0, eq);
    key.erase(key.find_last_not_of(' ') + 1);
    std::string value = argument.substr(eq + 1);
    value.erase(0, value.find_first_not_of(' '));
    return {key, value};
}

std::vector<OverrideSite> applyOverrides(toml::table& root, const std::vector<CaseOverride>& overrides,
                                         const std::string& fileName) {
    std::vector<OverrideSite> sites;
    for (const CaseOverride& o : overrides) {
        if (o.value.empty()) refuse(fileName, o, "no value after '=' (a TOML value: 50, 1.5e-10, true, \"lumped\")");
        const std::vector<KeyStep> steps = splitKey(fileName, o);
        toml::table* table = &root;
        std::string path;
        for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
            const KeyStep& step = steps[k];
            path += (path.empty() ? "" : ".") + step.name;
            toml::node* node = table->get(step.name);
            if (step.index) {
                toml::array* array = node ? node->as_array() : nullptr;
                const std::size_t count = array ? array->size() : 0;
                if (!array || !array->is_array_of_tables())
                    refuse(fileName, o, "the case has no [[" + path + "]] to index");
                if (*step.index >= count)
                    refuse(fileName, o,
                           "the case has " + std::to_string(count) + " [[" + path + "]] (" + path + "[0] to " + path +
                               "[" + std::to_string(count - 1) + "]); an override changes an entry that exists, "
                               "it does not add one: copy the case to add a layer");
                table = array->get(*step.index)->as_table();
                path += "[" + std::to_string(*step.index) + "]";
                continue;
            }
            if (!node) node = table->insert(step.name, toml::table{}).first->second.as_table();
            if (node->is_array_of_tables())
                refuse(fileName, o, "'" + path + "' is an array of tables [[" + path + "]]: name the entry, as " +
                                        path + "[0]." + steps[k + 1].name);
            if (!node->is_table())
                refuse(fileName, o, "'" + path + "' is " + written(*node) + " in the case, not a table");
            table = node->as_table();
        }
        const KeyStep& last = steps.back();
        if (last.index)
            refuse(fileName, o, "an override sets one key of an entry (" + last.name + "[" +
                                    std::to_string(*last.index) + "].KEY), not the whole entry");
        OverrideSite site;
        site.key = last.name;
        site.tablePath = path;
        site.tableIsRoot = table == &root;
        site.table = table->source();
        site.tableWritten = !site.tableIsRoot && table->source().begin.line > 0 && !table->is_inline();
        if (const toml::node* old = table->get(last.name)) {
            site.was = written(*old);
            site.value = old->source();
        }
        std::unique_ptr<toml::node> value = parseValue(o.value);
        const bool bare = value->is_string() && !(o.value.size() >= 2 && (o.value.front() == '"' || o.value.front() == '\''));
        site.newValue = bare ? written(*value) : o.value;
        value->visit([&](auto&& n) { table->insert_or_assign(last.name, std::move(n)); });
        sites.push_back(site);
    }
    return sites;
}

namespace {

/// The overridden file's text: each value replaced where it stood, or added under its table
std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

/// How the replaced value was written in the file itself (5.0e-5, not 5.0000000000000002e-05)
std::string wasWritten(const std::vector<std::string>& lines, const OverrideSite& s) {
    const auto& r = s.value;
    if (s.was.empty() || r.begin.line == 0 || r.begin.line != r.end.line || r.begin.line > lines.size()) return s.was;
    const std::string& line = lines[r.begin.line - 1];
    if (r.end.column - 1 > line.size() || r.end.column < r.begin.column) return s.was;
    return line.substr(r.begin.column - 1, r.end.column - r.begin.column);
}

std::string markOf(const CaseOverride& o, const std::string& was) {
    return o.text() + (was.empty() ? " (not in the file)" : " (was " + was + ")");
}

std::optional<std::string> splice(const std::string& fileText, const std::vector<CaseOverride>& overrides,
                                  const std::vector<OverrideSite>& sites) {
    std::vector<std::string> lines = linesOf(fileText);
    // edits from the last to the first, so that each keeps the place it was given
    struct Edit {
        std::size_t line, column, endLine, endColumn;  // 0-based; column = npos: insert a line
        std::string text, mark;
    };
    std::vector<Edit> edits;
    std::vector<std::string> appended;
    for (std::size_t k = 0; k < sites.size(); ++k) {
        const OverrideSite& s = sites[k];
        const std::string mark = "  # " + markOf(overrides[k], wasWritten(lines, s));
        if (!s.was.empty()) {
            if (s.value.begin.line == 0) return std::nullopt;  // set by an earlier override: no place in the file
            edits.push_back({std::size_t(s.value.begin.line - 1), std::size_t(s.value.begin.column - 1),
                             std::size_t(s.value.end.line - 1), std::size_t(s.value.end.column - 1), s.newValue, mark});
        } else if (s.tableIsRoot) {
            edits.push_back({0, std::string::npos, 0, 0, s.key + " = " + s.newValue, mark});
        } else if (s.tableWritten) {
            edits.push_back({std::size_t(s.table.begin.line), std::string::npos, 0, 0, s.key + " = " + s.newValue, mark});
        } else {
            if (s.tablePath.find('[') != std::string::npos) return std::nullopt;  // under an array of tables
            appended.push_back("\n[" + s.tablePath + "]");
            appended.push_back(s.key + " = " + s.newValue + mark);
        }
    }
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
        // on one line: the values from the right, then the lines inserted before it
        const bool aInsert = a.column == std::string::npos, bInsert = b.column == std::string::npos;
        if (a.line != b.line) return a.line > b.line;
        if (aInsert != bInsert) return bInsert;
        return !aInsert && a.column > b.column;
    });
    for (const Edit& e : edits) {
        if (e.column == std::string::npos) {
            if (e.line > lines.size()) return std::nullopt;
            lines.insert(lines.begin() + e.line, e.text + e.mark);
            continue;
        }
        if (e.endLine >= lines.size() || e.column > lines[e.line].size() || e.endColumn > lines[e.endLine].size())
            return std::nullopt;
        const std::string before = lines[e.line].substr(0, e.column), after = lines[e.endLine].substr(e.endColumn);
        lines.erase(lines.begin() + e.line + 1, lines.begin() + e.endLine + 1);
        lines[e.line] = before + e.text + after + e.mark;
    }
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    for (const std::string& line : appended) text += line + "\n";
    return text;
}

bool readsAs(const std::string& text, const toml::table& root) {
#if TOML_EXCEPTIONS
    try {
        return toml::parse(text) == root;
    } catch (const toml::parse_error&) {
        return false;
    }
#else
    toml::parse_result result = toml::parse(text);
    return result && result.table() == root;
#endif
}

}  // namespace

std::string effectiveCaseText(const std::string& fileText, const toml::table& root,
                              const std::vector<CaseOverride>& overrides, const std::vector<OverrideSite>& sites,
                              const std::string& fileName) {
    std::ostringstream head;
    head << "# The case as run: " << fileName << " with the command line's overrides, each marked on its line:\n";
    const std::vector<std::string> lines = linesOf(fileText);
    for (std::size_t k = 0; k < overrides.size(); ++k) head << "#   " << markOf(overrides[k], wasWritten(lines, sites[k])) << "\n";
    head << "\n";
    if (const auto text = splice(fileText, overrides, sites); text && readsAs(*text, root)) return head.str() + *text;
    std::ostringstream body;
    body << toml::toml_formatter(root);
    return head.str() + "# (written out by quicksand: the file's own layout and comments could not be kept)\n\n" +
           body.str() + "\n";
}

}  // namespace qs

#include "case/KeyLocations.hpp"

#include "core/Error.hpp"

namespace qs {

void KeyLocations::addTable(const std::string& path, int line) { tableLines_[path] = line; }

void KeyLocations::addKey(const std::string& path, std::string_view key, int line) {
    keyLines_[{path, std::string(key)}] = line;
}

KeyLocations::Table KeyLocations::table(const std::string& path) const {
    const auto at = tableLines_.find(path);
    QS_ASSERT(at != tableLines_.end());
    return Table(*this, path, at != tableLines_.end() ? at->second : 0);
}

bool KeyLocations::Table::has(std::string_view key) const {
    return all_->keyLines_.count({path_, std::string(key)}) > 0;
}

int KeyLocations::Table::lineOf(std::string_view key) const {
    const auto at = all_->keyLines_.find({path_, std::string(key)});
    return at != all_->keyLines_.end() && at->second > 0 ? at->second : line_;
}

std::string KeyLocations::Table::keyPath(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void KeyLocations::Table::fail(std::string_view key, const std::string& what) const {
    throw InputError(all_->file_, lineOf(key), keyPath(key), what);
}

}  // namespace qs

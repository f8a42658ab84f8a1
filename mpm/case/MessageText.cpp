#include "case/MessageText.hpp"

#include <sstream>

namespace qs {

std::string number(double v, int digits) {
    std::ostringstream s;
    s.precision(digits);
    s << v;
    return s.str();
}

std::string inQuotes(std::string_view text) { return "\"" + std::string(text) + "\""; }

std::string joinQuoted(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + inQuotes(items[i]);
    return out;
}

}  // namespace qs

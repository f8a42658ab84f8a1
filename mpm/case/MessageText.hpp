#pragma once
// How the input messages write values: numbers to ten significant digits (the value the user
// typed comes back as typed, 0.0093 and not 0.009300000000000001), strings in double quotes.
#include <string>
#include <string_view>
#include <vector>

namespace qs {

/// `v` to `digits` significant digits, without trailing zeros: "0.0093", "1e-06", "2.150537634".
std::string number(double v, int digits = 10);

/// "\"sand\"": a string value as it is written in TOML.
std::string inQuotes(std::string_view text);

/// "\"linear\", \"gimp\"": a list of allowed values.
std::string joinQuoted(const std::vector<std::string>& items);

}  // namespace qs

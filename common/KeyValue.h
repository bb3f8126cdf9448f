#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace nprgl {

using KeyValueList = std::vector<std::pair<std::string, std::string>>;

// Splits "a=1,b=2" (separator ',') or "frames=1,2;dir=x" (separator ';') into pairs, trimming
// blanks around keys and values. Returns false with a message for an item without '='.
bool parseKeyValues(std::string_view text, char separator, KeyValueList& out,
                    std::string& error);
// `s` without the blanks (spaces, tabs, carriage returns) at either end.
std::string_view trimBlanks(std::string_view s);

} // namespace nprgl

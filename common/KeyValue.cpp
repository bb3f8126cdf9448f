#include "common/KeyValue.h"

namespace nprgl {

std::string_view trimBlanks(std::string_view s)
{
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

bool parseKeyValues(std::string_view text, char separator, KeyValueList& out, std::string& error)
{
    KeyValueList list;
    while (!text.empty()) {
        size_t sep = text.find(separator);
        std::string_view item = trimBlanks(text.substr(0, sep));
        text = sep == std::string_view::npos ? std::string_view() : text.substr(sep + 1);
        if (item.empty()) continue;
        size_t eq = item.find('=');
        if (eq == std::string_view::npos || trimBlanks(item.substr(0, eq)).empty()) {
            error = "expected key=value, got '" + std::string(item) + "'";
            return false;
        }
        list.emplace_back(trimBlanks(item.substr(0, eq)), trimBlanks(item.substr(eq + 1)));
    }
    out = std::move(list);
    return true;
}

} // namespace nprgl

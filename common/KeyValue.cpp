#include "common/KeyValue.h"

namespace nprgl {

namespace {

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

} // namespace

bool parseKeyValues(std::string_view text, char separator, KeyValueList& out, std::string& error)
{
    KeyValueList list;
    while (!text.empty()) {
        size_t sep = text.find(separator);
        std::string_view item = trim(text.substr(0, sep));
        text = sep == std::string_view::npos ? std::string_view() : text.substr(sep + 1);
        if (item.empty()) continue;
        size_t eq = item.find('=');
        if (eq == std::string_view::npos || trim(item.substr(0, eq)).empty()) {
            error = "expected key=value, got '" + std::string(item) + "'";
            return false;
        }
        list.emplace_back(trim(item.substr(0, eq)), trim(item.substr(eq + 1)));
    }
    out = std::move(list);
    return true;
}

} // namespace nprgl

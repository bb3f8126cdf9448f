#include "FrameList.h"

#include <charconv>

namespace demo {

namespace {

bool parseFrameNumber(std::string_view text, int& value)
{
    if (text.empty()) {
        return false;
    }
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && value >= 1;
}

} // namespace

bool FrameList::parse(std::string_view text, std::string& error)
{
    ranges_.clear();
    if (text.empty()) {
        error = "empty frame list";
        return false;
    }
    while (true) {
        size_t comma = text.find(',');
        std::string_view item = text.substr(0, comma);
        size_t dash = item.find('-');
        int first = 0;
        int last = 0;
        bool ok = dash == std::string_view::npos
                      ? parseFrameNumber(item, first) && parseFrameNumber(item, last)
                      : parseFrameNumber(item.substr(0, dash), first)
                            && parseFrameNumber(item.substr(dash + 1), last);
        if (!ok || last < first) {
            error = "bad frame list item '" + std::string(item) + "'";
            ranges_.clear();
            return false;
        }
        ranges_.emplace_back(first, last);
        if (comma == std::string_view::npos) {
            return true;
        }
        text.remove_prefix(comma + 1);
    }
}

bool FrameList::contains(int frame) const
{
    for (const auto& [first, last] : ranges_) {
        if (frame >= first && frame <= last) {
            return true;
        }
    }
    return false;
}

} // namespace demo

#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace demo {

// A set of 1-based frame numbers written like "1,5,10" or "1-3,7".
class FrameList {
public:
    // Returns false and sets error when text is malformed.
    bool parse(std::string_view text, std::string& error);
    bool contains(int frame) const;
    bool empty() const { return ranges_.empty(); }

private:
    std::vector<std::pair<int, int>> ranges_;
};

} // namespace demo

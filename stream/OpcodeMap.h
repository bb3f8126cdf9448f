#pragma once

// OpcodeMap: a capture's opcode numbers onto this build's, by the command names the file
// carries (as apitrace stores call signatures), so captures outlive changes to gl.xml.

#include <cstdint>
#include <string>
#include <vector>

namespace nprgl {

class OpcodeMap {
public:
    // The numbering of a version-1 file, which is this build's own (its opcodes are the first
    // ones of every later list).
    OpcodeMap() = default;
    // names[i] is the command behind the file's opcode i. A name this build does not know
    // maps to nothing; only a call that uses it fails.
    explicit OpcodeMap(const std::vector<std::string>& names);

    bool identity() const { return mMap.empty(); }
    // This build's opcode for the file's, or kUnknown. Pseudo-calls keep their numbers.
    uint16_t translate(uint16_t fileOpcode) const
    {
        if (mMap.empty() || fileOpcode >= kPseudoFirst) return fileOpcode;
        return fileOpcode < mMap.size() ? mMap[fileOpcode] : kUnknown;
    }
    // Why translate() gave kUnknown, for an error message.
    std::string unknown(uint16_t fileOpcode) const;
    // How many of the file's named commands this build does not know.
    size_t unknownCount() const { return mUnknown; }

    static constexpr uint16_t kUnknown = 0xFEFF;

private:
    static constexpr uint16_t kPseudoFirst = 0xFF00; // op::kFrameEnd and after
    std::vector<uint16_t> mMap;
    std::vector<std::string> mNames;
    size_t mUnknown = 0;
};

} // namespace nprgl

#include "stream/CallPrinter.h"

#include "stream/CallDecoder.h"
#include "stream/Opcodes.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstring>

namespace nprgl {

namespace {

#include "nprgl_enums.inc"

// The name of value in one group of the registry (0: any group), or null.
const char* enumInGroup(uint32_t value, int group)
{
    auto it = std::lower_bound(std::begin(kEnumNames), std::end(kEnumNames),
                               std::pair<int, uint32_t>(group, value),
                               [](const EnumName& e, const std::pair<int, uint32_t>& key) {
                                   return std::pair<int, uint32_t>(e.group, e.value) < key;
                               });
    return it != std::end(kEnumNames) && it->group == group && it->value == value ? it->name
                                                                                   : nullptr;
}

const char* enumName(uint32_t value, int group)
{
    const char* name = group ? enumInGroup(value, group) : nullptr;
    return name ? name : enumInGroup(value, 0);
}

const char* kSlotNames[] = {"vertex", "normal", "color", "secondary_color", "fog_coord",
                            "index", "edge_flag"};

} // namespace

bool CallPrinter::printFrame(const uint8_t* data, size_t size, BlobSource* blobs,
                             const OpcodeMap* opcodes, const std::string& grep,
                             std::string& out, std::string& error, uint64_t* callCount,
                             uint64_t* callNumber)
{
    CallReader reader(data, size, blobs, opcodes);
    CallPrinter printer;
    printer.mOut = &out;
    printer.mGrep = grep;
    printer.mNumber = callNumber;
    if (!decodeCalls(reader, printer)) {
        error = reader.error();
        return false;
    }
    if (callCount) *callCount = printer.mCalls;
    return true;
}

void CallPrinter::begin(const char* name)
{
    mLine = name;
    mLine += '(';
    mFirstArg = true;
}

void CallPrinter::startArg(const char* name)
{
    if (!mFirstArg) mLine += ", ";
    mFirstArg = false;
    mLine += name;
    mLine += '=';
}

void CallPrinter::appendNumber(double value)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", value);
    mLine += buf;
}

void CallPrinter::arg(const char* name, double value)
{
    startArg(name);
    appendNumber(value);
}

void CallPrinter::argBits(const char* name, uint32_t value, int group)
{
    startArg(name);
    // Only the parameter's own group: in the shared table 0x4000 is GL_LIGHT0 too.
    const char* whole = group && value ? enumInGroup(value, group) : nullptr;
    if (whole) {
        mLine += whole; // GL_ALL_ATTRIB_BITS, GL_CLIENT_ALL_ATTRIB_BITS
        return;
    }
    std::string names;
    uint32_t unnamed = 0;
    for (uint32_t bit = 1; bit != 0; bit <<= 1) {
        if (!(value & bit)) continue;
        if (const char* e = group ? enumInGroup(bit, group) : nullptr) {
            names += (names.empty() ? "" : "|") + std::string(e);
        } else {
            unnamed |= bit;
        }
    }
    if (unnamed || names.empty()) {
        char text[16];
        std::snprintf(text, sizeof text, "0x%x", unnamed);
        names += (names.empty() ? "" : "|") + std::string(text);
    }
    mLine += names;
}

void CallPrinter::argEnum(const char* name, uint32_t value, int group)
{
    startArg(name);
    if (const char* e = enumName(value, group)) {
        mLine += e;
    } else {
        char buf[16];
        std::snprintf(buf, sizeof buf, "0x%x", value);
        mLine += buf;
    }
}

void CallPrinter::argBlob(const char* name, const void* data)
{
    startArg(name);
    mLine += data ? "<data>" : "NULL";
}

void CallPrinter::argString(const char* name, const char* text)
{
    startArg(name);
    mLine += text ? "\"" + std::string(text) + "\"" : "NULL";
}

void CallPrinter::argSources(const char* name, const CallReader::Sources& sources)
{
    startArg(name);
    size_t bytes = 0;
    for (int i = 0; i < sources.count; ++i) bytes += size_t(sources.lengths[i]);
    mLine += "<" + std::to_string(sources.count) + " strings, " + std::to_string(bytes) +
             " bytes>";
}

void CallPrinter::argPointer(const char* name, uint64_t value)
{
    startArg(name);
    char buf[24];
    std::snprintf(buf, sizeof buf, "0x%" PRIx64, value);
    mLine += buf;
}

void CallPrinter::end()
{
    mLine += ")\n";
    ++mCalls;
    std::string number;
    if (mNumber && !mPseudoLine) number = std::to_string((*mNumber)++) + ' ';
    mPseudoLine = false;
    if (mGrep.empty() || mLine.find(mGrep) < mLine.find('(')) *mOut += number + mLine;
}

bool CallPrinter::pseudo(CallReader& r, uint16_t opcode)
{
    if (opcode == op::kBatchRef) return expandBatchRef(r, *this, mDepth);
    if (opcode == op::kFrameEnd) {
        uint64_t frame = r.get<uint64_t>();
        if (!r.ok()) return false;
        ++mCalls;
        if (mGrep.empty()) *mOut += "-- end of frame " + std::to_string(frame) + " --\n";
        return true;
    }
    if (opcode == op::kUncaptured) {
        CallReader::Uncaptured calls;
        if (!r.getUncaptured(calls)) return false;
        std::string line = "-- not captured:";
        for (size_t i = 0; i < calls.size(); ++i) {
            line += (i ? ", " : " ") + calls[i].first + " " + std::to_string(calls[i].second);
        }
        if (mGrep.empty()) *mOut += line + " --\n";
        return true;
    }
    if (opcode == op::kCreated) {
        const uint32_t name = r.get<uint32_t>();
        if (!r.ok()) return false;
        ++mCalls;
        if (mGrep.empty()) *mOut += "-- created: " + std::to_string(name) + " --\n";
        return true;
    }
    if (opcode == op::kArrayData) {
        CallReader::Payload payload(r);
        uint8_t slot = r.get<uint8_t>();
        uint64_t offset = r.get<uint64_t>();
        size_t size = 0;
        r.getBytes(size);
        if (!payload.finish()) return false;
        begin("ArrayData");
        mPseudoLine = true;
        startArg("array");
        mLine += slot < 7    ? kSlotNames[slot]
                 : slot < 15 ? "texcoord" + std::to_string(slot - 7)
                             : "attrib" + std::to_string(slot - 15);
        arg("offset", double(offset));
        arg("bytes", double(size));
        end();
        return true;
    }
    return false;
}

} // namespace nprgl

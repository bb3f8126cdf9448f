#pragma once

#include "stream/CallReader.h"

#include <cstdint>
#include <string>

namespace nprgl {

// Prints decoded calls, one per line, with named arguments: glVertex3f(x=1, y=0, z=0.5).
class CallPrinter {
public:
    static constexpr bool kReplays = false;

    // Decodes and prints every call of one frame into out; returns false (with the offset in
    // error) on malformed input, keeping what was printed. grep, when not empty, keeps only
    // calls whose name contains it.
    // opcodes: the capture's numbering (null: this build's). callNumber, when given, numbers
    // each GL call's line from *callNumber on (as apitrace numbers them: the call's place in
    // its context's stream, whether grep keeps it or not) and is advanced past the frame.
    static bool printFrame(const uint8_t* data, size_t size, BlobSource* blobs,
                           const OpcodeMap* opcodes, const std::string& grep, std::string& out,
                           std::string& error, uint64_t* callCount = nullptr,
                           uint64_t* callNumber = nullptr);

    // The sink interface of decodeCall.
    void begin(const char* name);
    void arg(const char* name, double value);
    void argEnum(const char* name, uint32_t value, int group);
    // A bitfield (glClear's mask, glPushAttrib's): its bits' names in the registry's group
    // for the parameter, GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT; bits without one in hex.
    void argBits(const char* name, uint32_t value, int group);
    template <typename T>
    void argArray(const char* name, const T* values, size_t count)
    {
        startArg(name);
        if (!values) {
            mLine += "NULL";
            return;
        }
        mLine += '[';
        for (size_t i = 0; i < count && i < kMaxShown; ++i) {
            if (i) mLine += ", ";
            appendNumber(double(values[i]));
        }
        if (count > kMaxShown) mLine += ", ... " + std::to_string(count) + " values";
        mLine += ']';
    }
    void argBlob(const char* name, const void* data);
    void argString(const char* name, const char* text);
    void argSources(const char* name, const CallReader::Sources& sources);
    void argPointer(const char* name, uint64_t value);
    void end();
    template <typename T>
    T* scratch(size_t)
    {
        return nullptr;
    }
    bool pseudo(CallReader& r, uint16_t op);

private:
    static constexpr size_t kMaxShown = 16;

    void startArg(const char* name);
    void appendNumber(double value);

    std::string* mOut = nullptr;
    std::string mLine;
    std::string mGrep;
    bool mFirstArg = true;
    uint64_t mCalls = 0;
    uint64_t* mNumber = nullptr; // the next GL call's number, when numbering
    bool mPseudoLine = false;    // the line being built is nprgl's own record, not a GL call
    int mDepth = 0;
};

} // namespace nprgl
